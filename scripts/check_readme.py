#!/usr/bin/env python3
"""Runs the README's commands and checks its examples and tables, from the repository root.

    python3 scripts/check_readme.py [--build-dir DIR] [--python PYTHON]

Every command the README gives (the lines of its ```sh blocks and the inline `...` spans that
start with a command) is known here: run as written, run with fewer steps (the long ones), or
skipped with the reason printed. A command the README gains without an entry here fails the
check. Also:
  - the ```python block runs (with the CMake build's module: PYTHONPATH=DIR/python),
  - the ```cpp block is the part of examples/quick_start.cpp between its README markers (that
    program is built and run by the tests),
  - the README's tables are exactly what `scripts/reproduce.sh --tables-only docs` prints from the
    outputs kept in docs/,
  - the README has at most 400 lines.
The CTest test `readme` runs it on the build directory (python/CMakeLists.txt). Paths in the
commands written `build/...` are taken in DIR (default build).
"""

import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
MAX_LINES = 400

# Commands run as written (their expected output, when the README shows one, is checked).
RUN = {
    "bash scripts/docs.sh",
    "build/bin/quick_start data/bunny1k.off",
    "sscc demo --help",
}
# Long commands, run with fewer steps: the command as written -> the one run ({tmp}: a
# scratch folder).
REDUCED = {
    "build/bin/sscc demo": "build/bin/sscc demo --steps 3 --fcl-steps 1 --output {tmp}/demo-output",
}
# Commands not run here, and why.
SKIPPED = {
    "bash scripts/main.sh": "sets up, builds and runs the whole demo (300 steps); the build is this one and "
                            "the demo runs above with 3 steps",
    "bash scripts/test.sh": "is what CI runs, this check included",
    "bash scripts/build.sh": "builds the tree this check runs in",
    "PYTHONPATH=build/python python3 -c \"import sscc, numpy as np; m = sscc.read_mesh('data/bunny15k.off'); "
    "U = sscc.polynomial_basis(m, 27); b = sscc.SubspaceBvh(sscc.SubspaceModel(m, U, np.ones(27))); "
    "c = sscc.Certificates.precompute(b); d = sscc.SelfCcd(b, c); r = d.query(np.zeros(27), np.zeros(27)); "
    "print(r.pairs.shape, r.stats['root_certified'])\"":
        "the pytest suite runs it as written and checks its output (CTest test python: test_package.py, "
        "test_readme_one_liner_runs_with_the_python3_on_path); about 40 s, not twice",
    "bash scripts/reproduce.sh": "runs the benchmarks behind the tables (about 10 minutes with the caches, 10 more "
                                 "the first time); the tables are checked below against the outputs in docs/ "
                                 "(--tables-only)",
    "build/bin/sscc bench": "the paper's tables: about 6 minutes (scripts/reproduce.sh)",
    "bash scripts/scale.sh": "the pipeline at 10^4 to 10^6 triangles: minutes to hours (docs/benchmarks.md has "
                             "its table at 10^4 to 10^5)",
    "build/bin/sscc bench --only self-ccd --table-steps 5 --threads 1 --cache bench-cache":
        "every mesh of ../shared against FCL: 5 to 11 minutes to compute the certificates, then about 75 s "
        "(scripts/reproduce.sh)",
    "build/bin/sscc demo --scene spring": "44,100 steps after the spring's basis and certificates (about 90 s); the "
                                          "demo's code runs above with the bunnies",
    "build/bin/sscc": "names the command-line tool (its commands run above and below)",
    "cmake --install build": "installs into the system's prefix; the CTest test find_package_consumer installs "
                             "into a scratch prefix and builds against it",
    "pip install .": "scripts/python_package.sh (run by scripts/test.sh) installs the package into a fresh "
                     "virtual environment and tests it",
    "/usr/bin/python3 -m venv --system-site-packages venv": "scripts/python_package.sh, as for pip install .",
    "PIP_NO_INDEX=1 PIP_FIND_LINKS=/usr/share/python-wheels venv/bin/pip install .":
        "scripts/python_package.sh runs it (in a fresh virtual environment)",
    "venv/bin/python -c \"import sscc; print(sscc.PositionCcd, sscc.Scene)\"":
        "scripts/python_package.sh runs it in the environment it installed the package into",
}
# An inline `...` span is a command when it starts with one of these.
COMMAND_START = re.compile(r"^(bash |build/bin/|python3? |pip |cmake |sscc |/usr/bin/python3 |venv/|PYTHONPATH=)")


def code_blocks(text, language):
    return re.findall(r"^```" + language + r"\n(.*?)^```", text, flags=re.S | re.M)


def commands(text):
    """(command, expected output or None) for each line of the ```sh blocks (a following line
    '# OUTPUT' is the output the README shows), then the inline command spans."""
    found = []
    for block in code_blocks(text, "sh"):
        lines = block.rstrip("\n").split("\n")
        for i, line in enumerate(lines):
            if not line.strip() or line.startswith("#"):
                continue
            command = re.sub(r"\s{2,}#.*$", "", line).strip()  # a trailing comment
            expected = lines[i + 1][2:] if i + 1 < len(lines) and lines[i + 1].startswith("# ") else None
            found.append((command, expected))
    prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    for span in re.findall(r"`([^`]+)`", prose):
        span = " ".join(span.split())  # a span may wrap across lines
        if COMMAND_START.match(span) and span not in [c for c, _ in found]:
            found.append((span, None))
    return found


def in_build(command, build):
    return re.sub(r"(?<![\w/])build/", str(build) + "/", command)


def run(command, build, python, tmp, stdin=None):
    environment = dict(os.environ)
    command = command.replace("{tmp}", tmp)
    command = re.sub(r"^sscc ", "build/bin/sscc ", command)
    command = in_build(command, build)
    start = time.monotonic()
    result = subprocess.run(["bash", "-c", command], cwd=ROOT, env=environment, input=stdin, capture_output=True,
                            text=True)
    return result, time.monotonic() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build-dir", default="build")
    parser.add_argument("--python", default=sys.executable, help="the interpreter of the ```python block")
    args = parser.parse_args()
    build = pathlib.Path(args.build_dir).resolve()
    readme = (ROOT / "README.md").read_text()
    failures = []

    def fail(message):
        failures.append(message)
        print("FAIL  " + message)

    lines = readme.count("\n")
    print(f"README.md: {lines} lines (at most {MAX_LINES})")
    if lines > MAX_LINES:
        fail(f"README.md has {lines} lines")

    with tempfile.TemporaryDirectory(prefix="sscc-readme-") as tmp:
        for command, expected in commands(readme):
            if command in SKIPPED:
                print(f"SKIP  {command}\n      ({SKIPPED[command]})")
                continue
            if command in REDUCED:
                shown, command_run = command, REDUCED[command]
            elif command in RUN:
                shown, command_run = command, command
            else:
                fail(f"the README's command `{command}` is unknown to scripts/check_readme.py: add it to RUN, "
                     "REDUCED or SKIPPED")
                continue
            result, seconds = run(command_run, build, args.python, tmp)
            label = "RUN " if command_run == shown else "RUN*"
            print(f"{label}  {shown}" + ("" if command_run == shown else f"\n      as: {command_run}") +
                  f"\n      exit {result.returncode}, {seconds:.1f} s")
            if result.returncode != 0:
                fail(f"`{command_run}` exited with {result.returncode}:\n{result.stdout[-2000:]}{result.stderr[-2000:]}")
            elif expected is not None and result.stdout.strip() != expected.strip():
                fail(f"`{command_run}` printed {result.stdout.strip()!r}, the README shows {expected.strip()!r}")

        # The Python example, with the CMake build's module.
        for block in code_blocks(readme, "python"):
            environment = dict(os.environ, PYTHONPATH=str(build / "python"))
            start = time.monotonic()
            result = subprocess.run([args.python, "-"], cwd=ROOT, env=environment, input=block, capture_output=True,
                                    text=True)
            print(f"RUN   the ```python block ({block.count(chr(10))} lines)\n      exit {result.returncode}, "
                  f"{time.monotonic() - start:.1f} s")
            if result.returncode != 0:
                fail(f"the ```python block failed:\n{result.stderr[-3000:]}")

    # The C++ example is examples/quick_start.cpp's README part.
    example = (ROOT / "examples" / "quick_start.cpp").read_text()
    marked = example[example.index("// README: begin\n") + len("// README: begin\n"):example.index("  // README: end")]
    marked = "\n".join(line[2:] if line.startswith("  ") else line for line in marked.rstrip("\n").split("\n"))
    for block in code_blocks(readme, "cpp"):
        body = block.replace("#include <sscc/sscc.hpp>\n\n", "", 1).rstrip("\n")
        if body != marked:
            fail("the ```cpp block differs from examples/quick_start.cpp between its README markers")
        else:
            print("OK    the ```cpp block is examples/quick_start.cpp's (built and run by the tests)")

    # The tables, from the outputs kept in docs/.
    tables = subprocess.run(["bash", "scripts/reproduce.sh", "--tables-only", "docs"], cwd=ROOT, capture_output=True,
                            text=True, check=True).stdout
    for part in tables.split("<!-- table: ")[1:]:
        name, body = part.split(" -->\n", 1)
        if body.strip() not in readme:
            fail(f"the README's {name} table is not what scripts/reproduce.sh --tables-only docs prints")
        else:
            print(f"OK    the {name} table is scripts/reproduce.sh's, from docs/")

    if failures:
        print(f"check_readme: {len(failures)} failure(s)")
        return 1
    print("check_readme: every command ran or is skipped with its reason; examples and tables match")
    return 0


if __name__ == "__main__":
    sys.exit(main())
