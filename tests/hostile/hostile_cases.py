"""The hostile models: the files in models/, the generated ones, and the exact error each
must give. Shared by the command-line test and the web UI's /api/apply test.

Each case is (name, model file, expected message); ``{dir}`` in a message stands for the
folder of the model. All run with a memory limit of 256 MB for the buffers.
"""
from __future__ import annotations

import os
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = os.path.join(HERE, "models")
MAX_MEMORY = "256M"

_LIMIT = "is more than the memory limit of 256.0 MB (set with --max-memory or max_memory=)"

# Errors found while building: the message after "ikaros: error: ".
BUILD_ERRORS = {
    "size_huge": '{dir}/size_huge.ikg:1: <module name="C">: size of output "OUTPUT": a buffer '
                 f'of size 1000000000000: 3.6 TB {_LIMIT}',
    "size_square": '{dir}/size_square.ikg:1: <module name="C">: size of output "OUTPUT": a '
                   f'buffer of size 100000x100000: 37.3 GB {_LIMIT}',
    "size_overflow": '{dir}/size_overflow.ikg:1: <module name="C">: size of output "OUTPUT": a '
                     'buffer of size 999999970000000239271936: 3552713572.2 PB '
                     f'{_LIMIT}',
    "size_negative": '{dir}/size_negative.ikg:1: <module name="C">: size of output "OUTPUT": '
                     'the size -5 has a negative dimension',
    "size_fraction": '{dir}/size_fraction.ikg:1: <module name="C">: parameter "outputsize" of '
                     'C: "2.5" is not an integer',
    "size_infinite": '{dir}/size_infinite.ikg:1: <module name="C">: parameter "outputsize" of '
                     'C: "1e400" is not a finite integer',
    "memory_total": '{dir}/memory_total.ikg:1: <module name="C">: the model\'s buffers and '
                    f'delay rings: 381.5 MB {_LIMIT}; the largest is the buffer of C.OUTPUT '
                    '(152.6 MB)',
    "delay_range": '{dir}/delay_range.ikg:1: <connection>: delay "0:10000000" is longer than '
                   'the limit of 100000 ticks',
    "delay_huge": '{dir}/delay_huge.ikg:1: <connection>: delay "100000000000000000000" is '
                  'longer than the limit of 100000 ticks',
    "delay_ring": '{dir}/delay_ring.ikg:1: <module name="C">: the model\'s buffers and delay '
                  f'rings: 381.5 MB {_LIMIT}; the largest is the delay ring of C.OUTPUT '
                  '(381.5 MB)',
    "selector_far": '{dir}/selector_far.ikg:1: <connection>: the source selector is outside '
                    'its output bounds (shape (3,)) (C.OUTPUT -> P.INPUT (delay 1))',
    "target_selector_far": '{dir}/target_selector_far.ikg:1: <connection>: the target '
                           'selector reaches past the largest buffer allowed (67108864 '
                           'elements) (C.OUTPUT -> P.INPUT (delay 1))',
    "parameter_nan": '{dir}/parameter_nan.ikg:1: <module name="S">: parameter "step" of S: '
                     'nan is not a finite number',
    "parameter_inf": '{dir}/parameter_inf.ikg:1: <module name="S">: parameter "step" of S: '
                     '-inf is not a finite number',
    "parameter_overflow": '{dir}/parameter_overflow.ikg:1: <module name="S">: parameter '
                          '"step" of S: inf is not a finite number',
    "matrix_overflow": '{dir}/matrix_overflow.ikg:1: <module name="C">: parameter "data" of '
                       'C: 1e+39 is outside the float32 range',
    "exit_in_init": '{dir}/exit_in_init.ikg:1: <module name="E">: init failed: the module '
                    'called sys.exit(3)',
    "import_fails": '{dir}/import_fails.ikg:1: <module name="N">: class "NeedsPackage": '
                    '{dir}/NeedsPackage.py: cannot import: ModuleNotFoundError: No module '
                    "named 'ikaros_no_such_package' (the package may be installed with: pip "
                    'install ikaros_no_such_package)',
    "Selfish": '{dir}/Selfish.ikg:1: <module name="S">: class "Selfish" is the group file '
               '"Selfish.ikg", which this module is part of: a group file cannot be used '
               'inside itself',
    "external_text": '{dir}/external_text.ikg:1: <group name="X">: group file "notes.txt" is '
                     'not a model: {dir}/notes.txt:2: text outside the elements: "These are '
                     'notes, not a model."',
    "external_class": '{dir}/external_class.ikg:1: <group name="X">: group file '
                      '"Described.ikc" is not a model: {dir}/Described.ikc:1: the root element '
                      'is <class> but must be <group>',
    "include_text": '{dir}/include_text.ikg:1: included file "notes.txt" is not model text: '
                    '{dir}/notes.txt:2: text outside the elements: "These are notes, not a '
                    'model."',
    # generated below
    "nest_500": '{dir}/nest_500.ikg:1: <group name="G">: elements nest deeper than 200 '
                'levels',
    "nest_2000": '{dir}/nest_2000.ikg:1: <group name="G">: elements nest deeper than 200 '
                 'levels',
    "nest_20000": '{dir}/nest_20000.ikg:1: <group name="G">: elements nest deeper than 200 '
                  'levels',
    "files_nest": '{dir}/chain_99.ikg:1: <group name="G">: groups nest deeper than 100 '
                  'levels',
    "parentheses": '{dir}/parentheses.ikg:1: <module name="C">: parameter "outputsize" of C: '
                   f'"{"(" * 40}..." is not a number (the expression nests deeper than 100 '
                   f'levels: "{"(" * 40}...")',
    "brackets": '{dir}/brackets.ikg:1: <module name="C">: parameter "data" of C: brackets nest '
                'deeper than 32 levels',
    "braces": '{dir}/braces.ikg:1: <module name="C">: parameter "outputsize" of C: braces nest '
              'deeper than 100 levels',
    "expansion": '{dir}/expansion.ikg:1: <module name="C">: parameter "data" of C: the value '
                 'grows longer than 1000000 characters as its variables are resolved',
    "lookups": '{dir}/lookups.ikg:1: <module name="C">: parameter "data" of C: resolving the '
               'value takes more than 100000 variable lookups',
}

# Errors of the run (exit status 1): the lines on stderr.
RUN_ERRORS = {
    "exit_in_tick": ["fatal error: E: the module called sys.exit()"],
    "interrupt_in_tick": ["fatal error: E: the module raised KeyboardInterrupt"],
    "stop_fails": ["fatal error: SF: stop failed: RuntimeError: stop broke"],
}


def generate(folder: str) -> None:
    """Copy models/ into ``folder`` and write the generated models there."""
    shutil.copytree(MODELS, folder, dirs_exist_ok=True)

    def write(name, text):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)

    for n in (500, 2000, 20000):
        write(f"nest_{n}.ikg", '<group name="G">' * n + '<module class="Constant" name="C"/>'
              + "</group>" * n)
    # 150 files, each a group file that holds the next: nesting across files
    for k in range(150):
        inner = (f'<group name="G" external="chain_{k + 1}.ikg"/>' if k < 149 else
                 '<module class="Constant" name="C"/>')
        write(f"chain_{k}.ikg", f'<group name="G{k}">{inner}</group>')
    write("files_nest.ikg", '<group name="H"><group name="G" external="chain_0.ikg"/></group>')
    write("parentheses.ikg", '<group name="H"><module class="Constant" name="C" outputsize="'
          + "(" * 5000 + "1" + ")" * 5000 + '"/></group>')
    write("brackets.ikg", '<group name="H"><module class="Constant" name="C" data="'
          + "[" * 5000 + "1" + "]" * 5000 + '"/></group>')
    write("braces.ikg", '<group name="H"><module class="Constant" name="C" outputsize="'
          + "{" * 20000 + "1" + "}" * 20000 + '"/></group>')
    # each variable twice the one before: 1000 * 2^39 characters
    attrs = f'a0="{"x" * 1000}" ' + " ".join(f'a{i}="@a{i - 1}@a{i - 1}"' for i in range(1, 40))
    write("expansion.ikg", f'<group name="H" {attrs}><module class="Constant" name="C" '
          'data="@a39"/></group>')
    # the same with empty values: nothing grows, but 2^60 lookups
    attrs = 'a0="" ' + " ".join(f'a{i}="@a{i - 1}@a{i - 1}"' for i in range(1, 61))
    write("lookups.ikg", f'<group name="H" {attrs}><module class="Constant" name="C" '
          'data="@a60"/></group>')
