"""The compliant-robot classes of Ikaros 3: ServosSimulation (the simulated servos they run
against), ForceCheck, PositionSelection, CurrentPositionMapping and ServoControlTuning.
Expected values are the formulas of each class's description, computed here with NumPy."""
import json

import numpy as np
import pytest

from ikaros.testing import load_body

STALL, SPEED = 5200.0, 270.0            # MX-106(2.0): stall current (mA), no-load speed (°/s), e-Manual


def servo_steps(goal, goal_current, limit, ticks, dt, start=180.0):
    """ServosSimulation's servos: the controller asks for the stall current × error / 10°,
    limited to min(|goal current|, limit); speed = no-load speed × current / stall current."""
    present = np.full(len(goal), start)
    rows = []
    for _ in range(ticks):
        error = np.asarray(goal, float) - present
        allowed = np.minimum(np.abs(goal_current), limit)
        current = np.clip(STALL * error / 10.0, -allowed, allowed)
        step = SPEED * current / STALL * dt
        present = present + np.where(np.abs(step) >= np.abs(error), error, step)
        rows.append((present.copy(), current))
    return rows


def test_servos_simulation_moves_with_the_current_it_is_allowed(tmp_path):
    body = ('<module class="Constant" name="G" data="200 170 180"/>\n'
            '<module class="Constant" name="C" data="2600 5200 1000"/>\n'
            '<module class="Constant" name="L" data="5200 1300 5200"/>\n'
            '<module class="ServosSimulation" name="S"/>\n'
            '<connection source="G.OUTPUT" target="S.GoalPosition" delay="0"/>\n'
            '<connection source="C.OUTPUT" target="S.GoalCurrent" delay="0"/>\n'
            '<connection source="L.OUTPUT" target="S.CurrentLimit" delay="0"/>\n')
    net = load_body(tmp_path, body, dialect="3", tick_duration="0.05")
    for present, current in servo_steps([200, 170, 180], [2600, 5200, 1000], [5200, 1300, 5200], 12, 0.05):
        net.step()
        assert net.output("S.PresentPosition") == pytest.approx(present, abs=1e-3)
        assert net.output("S.PresentCurrent") == pytest.approx(current, abs=1e-2)
    assert net.output("S.PresentPosition") == pytest.approx([200, 170, 180], abs=1e-3)
    net.close()


def test_force_check_smooths_the_current_and_gives_way_at_the_limit(tmp_path):
    body = ('<module class="Constant" name="G" data="200 200 185"/>\n'
            '<module class="Constant" name="P" data="180 180 180"/>\n'
            '<module class="Constant" name="I" data="100 50 100"/>\n'
            '<module class="Constant" name="L" data="100 100 100"/>\n'
            '<module class="ForceCheck" name="F"/>\n'
            '<connection source="G.OUTPUT" target="F.GoalPositionIn" delay="0"/>\n'
            '<connection source="P.OUTPUT" target="F.PresentPosition" delay="0"/>\n'
            '<connection source="I.OUTPUT" target="F.PresentCurrent" delay="0"/>\n'
            '<connection source="L.OUTPUT" target="F.CurrentLimit" delay="0"/>\n')
    net = load_body(tmp_path, body, dialect="3")
    wanted = np.minimum(8.5 * np.array([20.0, 20.0, 5.0]), 100.0)
    out = np.zeros(3)
    for _ in range(4):
        net.step()
        out = 0.7 * out + 0.3 * wanted
        assert net.output("F.CurrentOutput") == pytest.approx(out, abs=1e-3)
    # 20° off and at its limit: gives way; below its limit, or within 10°: keeps its goal
    assert net.output("F.GoalPositionOut").tolist() == [180, 200, 185]
    net.close()


def test_force_check_against_the_simulated_servos(tmp_path):
    """A servo whose current is limited to 100 mA crawls: it is far from its goal at its limit,
    so ForceCheck gives way; with 5200 mA it is not held back and keeps its goal."""
    body = ('<module class="Constant" name="G" data="220 220"/>\n<module class="Constant" name="L" data="100 5200"/>\n'
            '<module class="ForceCheck" name="F"/>\n<module class="ServosSimulation" name="S"/>\n'
            '<connection source="G.OUTPUT" target="F.GoalPositionIn" delay="0"/>\n'
            '<connection source="L.OUTPUT" target="F.CurrentLimit" delay="0"/>\n'
            '<connection source="L.OUTPUT" target="S.CurrentLimit" delay="0"/>\n'
            '<connection source="F.CurrentOutput" target="S.GoalCurrent" delay="0"/>\n'
            '<connection source="F.GoalPositionOut" target="S.GoalPosition" delay="0"/>\n'
            '<connection source="S.PresentPosition" target="F.PresentPosition"/>\n'
            '<connection source="S.PresentCurrent" target="F.PresentCurrent"/>\n')
    net = load_body(tmp_path, body, dialect="3", tick_duration="0.05")
    gave_way = False
    for _ in range(80):
        net.step()
        gave_way |= net.output("F.GoalPositionOut")[0] < 220
    assert gave_way
    assert net.output("F.GoalPositionOut")[1] == 220 and net.output("S.PresentPosition")[1] > 210
    net.close()


def test_position_selection_takes_the_row_or_the_elements_ranked_highest(tmp_path):
    rows = np.arange(3 * 19, dtype=float).reshape(3, 19)
    data = "; ".join(" ".join(str(v) for v in row) for row in rows)

    def select(ranking):
        body = (f'<module class="Constant" name="P" data="{data}"/>\n'
                f'<module class="Constant" name="R" data="{ranking}"/>\n<module class="PositionSelection" name="S"/>\n'
                '<connection source="P.OUTPUT" target="S.PositionInput" delay="0"/>\n'
                '<connection source="R.OUTPUT" target="S.InputRanking" delay="0"/>\n')
        net = load_body(tmp_path, body, dialect="3")
        net.step()
        out = net.output("S.PositionOutput").copy()
        net.close()
        return out
    assert select("0.2 0.9 0.5").tolist() == rows[1].tolist()
    assert select("0 0 -1").tolist() == [0.0] * 19                          # nothing wins: kept (0 at start)
    per_element = np.where(np.arange(19) % 2 == 0, 1.0, 0.0)
    ranking = np.vstack([per_element, 1 - per_element, np.zeros(19)])
    expected = np.where(np.arange(19) % 2 == 0, rows[0], rows[1])
    assert select("; ".join(" ".join(str(v) for v in r) for r in ranking)).tolist() == expected.tolist()


def test_current_position_mapping_visits_the_range_and_maps_the_current(tmp_path):
    """The Epi torso simulated by DynamixelController (6 servos); its currents here are 500 mA
    for the neck (the simulation has none)."""
    body = ('<module class="CurrentPositionMapping" name="M" NumberTransitions="3"/>\n'
            '<module class="DynamixelController" name="D" robot="EpiGray" Simulate="yes" SimulationRate="1"/>\n'
            '<module class="Constant" name="I" data="500 -500 0 0 0 0"/>\n'
            '<connection source="M.GoalPosition" target="D.GOAL_POSITION" delay="0"/>\n'
            '<connection source="D.PRESENT_POSITION" target="M.PresentPosition"/>\n'
            '<connection source="I.OUTPUT" target="M.PresentCurrent" delay="0"/>\n')
    net = load_body(tmp_path, body, dialect="3", tick_duration="0.05")
    # 3 positions over 114..237 and 153..219; the neck's limits (122..237, 130..240) clip 114
    stops = [[114, 153], [175.5, 186], [237, 219]]
    visited = []
    currents = []
    for _ in range(400):
        net.step()
        goal = net.output("M.GoalPosition")[:2].tolist()
        if not visited or goal != visited[-1]:
            visited.append(goal)
        currents.append(net.output("M.GoalCurrent")[:3].tolist())
    assert visited[:5] == [stops[0], stops[1], stops[2], stops[1], stops[0]]
    assert currents[0] == pytest.approx([600, 600, 0])      # 1.2 × the 500 mA learned; the others: their own
    assert currents[-1] == pytest.approx([600, 600, 0])
    net.close()


def test_servo_control_tuning_runs_its_sequence_and_saves(tmp_path):
    body = ('<module class="ServoControlTuning" name="T" ServoParameters="180,200,150,100,900,0,0" '
            'NumberTransitions="4" RunSequence="yes" Save="yes" robot="EpiBlue" Servo="NeckPan"/>\n')
    net = load_body(tmp_path, body, dialect="3", tick_duration="0.5")
    rows = []
    for _ in range(11):
        net.step()
        rows.append((net.output("T.Position").tolist(), net.output("T.Current").tolist()))
    step = 360 / 4096
    # two ticks a move; NeckPan's limits (raw 1750..2500) clip 150° (1706.7) to 1750
    goals = [200, 200, 1750 * step, 1750 * step, 200, 200, 1750 * step, 1750 * step, 180, 180, 180]
    assert [p[0] for p, _ in rows] == pytest.approx(goals, abs=0.05)
    assert [p[1] for p, _ in rows] == pytest.approx([g / step for g in goals], abs=0.6)
    assert [c[0] for _, c in rows] == pytest.approx([300, 300, 500, 500, 700, 700, 900, 900, 100, 100, 100])
    saved = json.loads((tmp_path / "ServoControlTuning_EpiBlue_NeckPan.json").read_text())
    assert saved["positions"] == [180, 200, 150] and saved["limits_raw"] == [1750, 2500]
    net.close()
