"""A schema-driven fuzz test of the HTTP API (schemathesis, from /api/openapi.json): no
request gets a 5xx, every answer has a documented status and matches its schema, and no
request the schema calls valid is refused as malformed (400, 413, 415): the description
states the rules the server enforces."""
from __future__ import annotations

import warnings

import pytest

import schemathesis  # noqa: E402
from hypothesis import HealthCheck, given, settings  # noqa: E402
from schemathesis import checks as st_checks  # noqa: E402
from schemathesis.specs.openapi import checks as oa_checks  # noqa: E402

warnings.filterwarnings("ignore", message=".*httpx.*")

import ikaros  # noqa: E402
from ikaros.module import WARNING  # noqa: E402
from ikaros.webui.server import create_app  # noqa: E402

pytestmark = pytest.mark.filterwarnings("ignore")
EXAMPLES = 40  # per operation: 17 s in all (100 took a minute of the test run)

MODEL = '''<group name="F">
    <module class="Constant" name="C" data="1 2; 3 4" />
    <module class="Scale" name="S" factor="2" />
    <connection source="C.OUTPUT" target="S.INPUT" />
    <view name="V"><plot source="S.OUTPUT" x="0" y="0" /></view>
</group>
'''


@pytest.fixture(scope="module")
def app(tmp_path_factory):
    folder = tmp_path_factory.mktemp("fuzz")
    (folder / "f.ikg").write_text(MODEL)
    net = ikaros.load(str(folder / "f.ikg"))
    net.log_level = WARNING
    application = create_app(net, build_timeout=5)
    yield application
    for n in {net, application.state.ui.net}:
        n.controller.stop()
        n.controller.join(5)
        n.close()


@schemathesis.check
def valid_requests_are_not_refused(ctx, response, case):
    """A request the schema calls valid may be answered 404 (no such module), 403, 409 or
    422 (not a valid model), but never as malformed (400, 413, 415)."""
    if case.meta is not None and case.meta.generation.mode.is_positive and \
            response.status_code in (400, 413, 415):
        raise AssertionError(f"a schema-valid request was refused with "
                             f"{response.status_code}: {response.text[:300]}")


CHECKS = [st_checks.not_a_server_error, oa_checks.status_code_conformance,
          oa_checks.content_type_conformance, oa_checks.response_schema_conformance,
          valid_requests_are_not_refused]


def test_the_api_holds_up_against_generated_requests(app):
    api = schemathesis.openapi.from_asgi("/api/openapi.json", app)
    failures = []
    for result in api.get_all_operations():
        operation = result.ok()

        @given(case=operation.as_strategy())
        @settings(max_examples=EXAMPLES, deadline=None, derandomize=True, database=None,
                  suppress_health_check=list(HealthCheck))
        def fuzz(case):
            case.call_and_validate(checks=CHECKS)
        try:
            fuzz()
        except (Exception, BaseExceptionGroup) as e:   # all operations tried, all failures shown
            failures.append(f"{operation.label}: {e}")
    assert not failures, "\n\n".join(failures)
