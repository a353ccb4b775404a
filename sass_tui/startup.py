"""What each way of starting sass must not import, and why: the one list of
start-up paths.  tests/test_startup.py runs every row (the verb in a fresh
interpreter, on a copy of the shipped database where it reads one) and fails
if a module named in `forbidden` was imported.

Each row says only what is true today (every list was measured by running
the path and reading `sys.modules`); a module `import numpy` itself brings
(numpy.ma and secrets on numpy 1.26) is not held against a path that may
import numpy.  An import inside a function elsewhere in sass_tui carries
`# deferred: MODULE — off PATH, ... (sass_tui/startup.py)` when it keeps
MODULE off one of these paths, by the row's `name`
(tests/test_deferred_imports.py checks both).

Pure data: nothing in sass imports it, and it imports only typing.
"""

from __future__ import annotations

from typing import NamedTuple


class StartupPath(NamedTuple):
    name: str  # how a `# deferred:` comment names the path
    argv: tuple[str, ...]  # `sass`'s arguments; () is the TUI
    forbidden: tuple[str, ...]  # modules the path must not import
    why: str
    # The TUI's moment of the check: "drawn" (the first screen is on the
    # terminal, SpreadsheetScreen._first_screen_drawn) or "settled" (a frame
    # later, the figure panel drawn); a verb is checked when it has returned.
    moment: str = "end"
    needs_db: bool = False  # run with `--db` on a copy of the shipped database
    status: int = 0  # the exit status the argv is expected to give


# Off every path here: lark only reads a .fig file (model/files/fig_reader.py; a query
# is parsed by the generated stand-alone parser, db/query/_query_parser.py); pint
# only checks the unit table in the tests; pygltflib only reads exported glTF
# files back in the tests.
NEVER = ("lark", "pint", "pygltflib")
# The query language's generated parser: only a path that parses a query.
QUERY_PARSER = ("sass_tui.db.query._query_parser",)
# Textual and what draws or serves it: only the TUI and `sass serve`.
UI = ("textual", "rich", "textual_canvas", "textual_plotext", "textual_serve", "aiohttp")
# The engines past SQLite: PostgreSQL on an address, DuckDB for the column
# copy of 200,000 people and more (db/query/accelerator.py).
ENGINES = ("psycopg", "duckdb")
# Standard-library modules a command that writes nothing to a temporary file,
# logs nothing and copies no file need not pay for.
NOT_FOR_A_SHORT_COMMAND = ("logging", "shutil", "tempfile", "importlib.metadata", "asyncio")
# What the TUI's other screens, the database and the prediction model bring.
OTHER_SCREENS = (
    "sqlite3",
    "sass_tui.db",
    "sass_tui.model.population.prediction",
    "sass_tui.ui.query.query_screen",
)

# fmt: off
PATHS: tuple[StartupPath, ...] = (
    StartupPath(
        "the first screen",
        (),
        (*NEVER, *QUERY_PARSER, *ENGINES, *OTHER_SCREENS, "numpy", "textual_canvas",
         "textual_plotext",
         "textual_serve", "aiohttp", "xml.etree.ElementTree", "importlib.metadata",
         "sass_tui.ui.spreadsheet.figure_screen"),
        "`sass` start-up <= 1.3x a bare Textual app (benchmarks/cli_ratios.py): the default"
        " figure is read and computed in plain floats; numpy (~31 ms) waits a frame",
        moment="drawn",
    ),
    StartupPath(
        "the first screen's next frame",
        (),
        (*NEVER, *QUERY_PARSER, *ENGINES, *OTHER_SCREENS, "textual_plotext", "textual_serve",
         "aiohttp",
         "xml.etree.ElementTree", "numpy.ma", "secrets"),
        "the figure panel and the strength sheet (numpy, textual-canvas) come one frame"
        " later; the query screen, the database, exports and the first edit's modules wait"
        " until used",
        moment="settled",
    ),
    StartupPath(
        "sass --help",
        ("--help",),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "numpy", "sqlite3",
         "platformdirs", "pathlib", "urllib.parse", "ipaddress",
         "pickle", "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui"),
        "the verbs are listed from the light table in sass_tui/cli/__init__.py: no verb's"
        " module is imported (each imports what it needs at its top;"
        " tests/cli/test_verbs.py)",
    ),
    StartupPath(
        "sass --version",
        ("--version",),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, "numpy", "sqlite3", "logging", "asyncio", "pickle",
         "sass_tui.db", "sass_tui.ui"),
        "importlib.metadata reads the version; nothing else is needed",
    ),
    StartupPath(
        "sass fig",
        ("fig", "-o", "X.fig"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy.ma", "secrets", "xml.etree.ElementTree", "sass_tui.db",
         "sass_tui.ui", "sass_tui.model.body.landmarks"),
        "`sass fig -o X.fig` <= 1.6x `python -c 'import numpy'` (benchmarks/cli_ratios.py):"
        " the figure needs numpy and the model, no database and no temporary file's name",
    ),
    StartupPath(
        "sass export hanim",
        ("export", "hanim", "-o", "X.x3d"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy.ma",
         "secrets", "sass_tui.db", "sass_tui.ui"),
        "the X3D document needs the figure and xml.etree, no database",
    ),
    StartupPath(
        "sass export gltf",
        ("export", "gltf", "-o", "X.glb"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, "logging", "asyncio", "sqlite3", "platformdirs",
         "numpy.ma",
         "secrets", "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui"),
        "the glTF body needs the figure's humanoid, not the X3D writer nor a database",
    ),
    StartupPath(
        "sass strength",
        ("strength", "elbow_flexion"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy.ma", "secrets", "xml.etree.ElementTree", "sass_tui.db",
         "sass_tui.ui", "sass_tui.model.files.atomic"),
        "the strength of the default figure needs the strength file and the model only",
    ),
    StartupPath(
        "sass strength arm_force",
        ("strength", "arm_force", "--direction", "up"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy.ma", "secrets", "xml.etree.ElementTree", "sass_tui.db",
         "sass_tui.ui", "sass_tui.cli.common.person_option"),
        "the Arm Force Field at the default figure's hand needs the posture and the model;"
        " the database only for --person (cli/common/person_option.py)",
    ),
    StartupPath(
        "sass task",
        ("task", "shoulder_y=60", "elbow_y=30", "--right-load", "50N"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3", "platformdirs", "numpy.ma",
         "secrets", "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui"),
        "a task for women and men needs the figure's humanoid, the Arm Force Field and"
        " Anderson et al. 2007, no database (only --person and --target open one)",
    ),
    StartupPath(
        "sass reach",
        ("reach", "--gender", "female", "--point", "30,120,50"),
        (*NEVER, *UI, *ENGINES, "logging", "asyncio", "sqlite3", "platformdirs", "numpy.ma",
         "secrets", "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui"),
        "a figure's reach needs its humanoid and the glTF writer, no database (only"
        " --person, --known, --target and --virtual open one: cli/reach_people.py)",
    ),
    StartupPath(
        "sass niosh",
        ("niosh", "--h", "40cm", "--v", "60cm", "--d", "80cm", "--f", "2", "--load", "12kg"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy", "csv", "dataclasses", "inspect", "statistics", "gzip",
         "string", "pathlib", "urllib.parse", "ipaddress",
         "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui", "sass_tui.model.body",
         "sass_tui.model.datasets", "sass_tui.model.names", "sass_tui.model.files",
         "sass_tui.model.strength.niosh_tasks", "sass_tui.cli.niosh_job"),
        "the lifting equation is plain floats and two tables read by model/shipped.py: no"
        " numpy, no database, no row tables; a job file's reader (pathlib) and parser"
        " (csv), ~4 ms, only for --tasks (cli/niosh_job.py)",
    ),
    StartupPath(
        "sass handling",
        ("handling", "lift", "--h", "0.38", "--v", "1.03", "--d", "0.51", "--load", "10kg"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "sqlite3",
         "platformdirs", "numpy", "csv", "dataclasses", "inspect", "statistics", "gzip",
         "string", "pathlib", "urllib.parse", "ipaddress",
         "xml.etree.ElementTree", "sass_tui.db", "sass_tui.ui", "sass_tui.model.body",
         "sass_tui.model.datasets", "sass_tui.model.names", "sass_tui.model.files"),
        "the Liberty Mutual equations are plain floats and math.erf, their table read by"
        " model/shipped.py (os.path, not pathlib): numpy and the figure"
        " only for a posture (cli/handling_figure.py), the database only for --target and"
        " --virtual (cli/handling_people.py)",
    ),
    StartupPath(
        "sass query",
        ("query", "(stature > 70 in OR mass < 60 kg) AND girth.right_upper_arm.z > 20 cm"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "pickle", "dataclasses", "inspect",
         "numpy", "secrets", "platformdirs", "xml.etree.ElementTree", "sass_tui.ui",
         "sass_tui.model.population.prediction", "sass_tui.db.query.accelerator", "sass_tui.db.engine.postgres",
         "json", "csv", "sass_tui.model.datasets"),
        "`sass query` <= 5x `python -c pass` (benchmarks/cli_ratios.py): the generated"
        " parser, the unit table (not pint), SQLite and the table writer; argparse's help"
        " formatter without shutil; no column copy below its size; json only for --format"
        " json (1.1 ms), the PostgreSQL module only for an address",
        needs_db=True,
    ),
    StartupPath(
        "sass query --format csv",
        ("query", "--format", "csv", "stature > 70 in"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "pickle", "dataclasses", "inspect",
         "numpy", "secrets", "platformdirs", "xml.etree.ElementTree", "sass_tui.ui",
         "sass_tui.model.population.prediction", "sass_tui.db.query.accelerator", "sass_tui.db.engine.postgres",
         "json"),
        "as `sass query`: \"70 in\" is converted from the unit table, and csv is the writer",
        needs_db=True,
    ),
    StartupPath(
        "sass query --count",
        ("query", "--count", "gender = male"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "pickle", "numpy", "secrets",
         "platformdirs", "xml.etree.ElementTree", "sass_tui.ui", "sass_tui.model.population.prediction",
         "uuid"),
        "a count asks the column copy's module whether a copy exists; below its size"
        " SQLite counts, without duckdb or numpy",
        needs_db=True,
    ),
    StartupPath(
        "sass person",
        ("person", "1"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "numpy.ma", "secrets",
         "platformdirs",
         "xml.etree.ElementTree", "sass_tui.ui", "sass_tui.model.population.prediction",
         "sass_tui.db.query.accelerator"),
        "one person's record: no query language, no prediction",
        needs_db=True,
    ),
    StartupPath(
        "sass population",
        ("population", "--query", "gender = male", "-o", "X.dat"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "pickle", "inspect", "secrets",
         "platformdirs",
         "xml.etree.ElementTree", "sass_tui.ui", "sass_tui.model.population.prediction",
         "sass_tui.db.query.accelerator", "sass_tui.db.populations.targets", "sass_tui.model.population.targets"),
        "the population files need the query, the people and numpy's statistics only",
        needs_db=True,
    ),
    StartupPath(
        "sass predict",
        ("predict", "--gender", "male", "--known", "stature=180"),
        (*NEVER, *UI, *ENGINES, "asyncio", "importlib.metadata", "numpy.ma",
         "secrets", "platformdirs", "xml.etree.ElementTree", "sass_tui.ui",
         "sass_tui.db.query.accelerator", "sass_tui.model.body.figure", "sass_tui.model.files.figfile",
         "sass_tui.model.body.hanim", "sass_tui.model.files.gltf"),
        "the regression needs the people and numpy, not the figure nor the exports' writers"
        " (only -o writes a figure)",
        needs_db=True,
    ),
    StartupPath(
        "sass fit",
        ("fit", "stature <= 190 cm"),
        (*NEVER, *UI, *ENGINES, "asyncio", "importlib.metadata", "numpy.ma",
         "secrets", "platformdirs", "xml.etree.ElementTree", "sass_tui.ui",
         "sass_tui.db.query.accelerator", "sass_tui.db.populations.targets", "sass_tui.db.populations.predict"),
        "the fit test needs the query, the people and numpy only",
        needs_db=True,
    ),
    StartupPath(
        "sass family",
        ("family", "--gender", "male", "--measures", "stature,mass", "-o", "family"),
        (*NEVER, *UI, *ENGINES, "asyncio", "importlib.metadata", "numpy.ma",
         "secrets", "platformdirs", "sass_tui.ui", "sass_tui.db.query.accelerator",
         "sass_tui.db.populations.targets"),
        "the family needs the people, the prediction and the X3D writer, no TUI",
        needs_db=True,
    ),
    StartupPath(
        "sass target",
        ("target", "--list"),
        (*NEVER, *UI, *ENGINES, *NOT_FOR_A_SHORT_COMMAND, "pickle", "inspect", "numpy.ma",
         "secrets", "platformdirs",
         "xml.etree.ElementTree", "sass_tui.ui", "sass_tui.model.population.prediction",
         "sass_tui.db.query.accelerator"),
        "listing the stored targets reads the database only",
        needs_db=True,
    ),
    StartupPath(
        "sass stats",
        ("stats", "stature", "mass", "--gender", "female"),
        (*NEVER, *UI, *ENGINES, "asyncio", "importlib.metadata", "numpy.ma",
         "secrets", "platformdirs", "xml.etree.ElementTree", "sass_tui.ui",
         "sass_tui.db.query.accelerator"),
        "the table reads the people's values and weights, no TUI, no other engine (the "
        "shipped virtual population's maker, db/populations/virtual.py, brings the prediction's tempfile)",
        needs_db=True,
    ),
    StartupPath(
        "sass db init",
        ("--db", "new.db", "db", "init"),
        (*NEVER, *UI, *ENGINES, "asyncio", "importlib.metadata", "platformdirs",
         "xml.etree.ElementTree", "sass_tui.ui"),
        "building the default database needs the shipped files and SQLite; the shipped "
        "target and virtual population made with it (db/populations/virtual.py) bring a query (lark) "
        "and the prediction model, no other engine, no TUI",
    ),
    StartupPath(
        "sass serve",
        ("serve", "--host", "0.0.0.0"),
        (*NEVER, *QUERY_PARSER, *UI, *ENGINES, "numpy", "sqlite3", "tempfile", "importlib.metadata",
         "platformdirs", "sass_tui.db"),
        "an address it will not serve on is refused before the web server is imported",
        status=2,
    ),
)
# fmt: on
