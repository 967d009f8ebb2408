#!/usr/bin/env python3
"""The README's tables, in the README's form, from the outputs of the commands behind them.

    python3 scripts/readme_tables.py DIR

reads, in DIR:
  demo_bunnies.md     the output of `build/bin/sscc demo` (standard output)
  bench.md            bench-output/bench.md of `build/bin/sscc bench`
  bench_self_ccd.md   bench-output/bench_self_ccd.md of `build/bin/sscc bench --only self-ccd
                      --table-steps 5 --threads 1 --cache bench-cache`
and prints three blocks, each after a line `<!-- table: NAME -->` (demo, paper, fcl), exactly as
the README quotes them. scripts/reproduce.sh runs the commands and then this; docs/ keeps the
outputs behind the README's current tables, and scripts/check_readme.py checks that the README
holds what this prints from them.
"""

import pathlib
import sys

# The demo's summary lines the README quotes, by their start (the scene line above the table
# and the "impacts and strikes" line are left out).
DEMO_LINES = ("speedup SSCC over traditional", "the traditional query ran", "threads:", "agreement:",
              "contact response:", "interpenetration", "largest deformation", "demo:")
# The self-CCD table's columns the README keeps, by header.
FCL_COLUMNS = ("mesh", "triangles", "amplitude", "traditional", "cones", "SSCC", "FCL", "FCL vs cones",
               "root-certified steps", "identical")


def first_table(lines, header_start):
    """The lines of the first Markdown table whose header starts with header_start."""
    for i, line in enumerate(lines):
        if line.startswith(header_start):
            j = i
            while j < len(lines) and lines[j].startswith("|"):
                j += 1
            return lines[i:j]
    raise SystemExit(f"readme_tables: no table starting with {header_start!r}")


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def demo(lines):
    table = first_table(lines, "| method | mean ms/step")
    end = lines.index(table[-1]) + 1
    summary = [line for line in lines[end:] if line.startswith(DEMO_LINES)]
    return "\n".join(table) + "\n\n```\n" + "\n".join(summary) + "\n```"


def paper(lines):
    return "\n".join(first_table(lines, "| example | triangles |"))


def fcl(lines):
    table = first_table(lines, "| mesh | triangles |")
    header = cells(table[0])
    try:
        keep = [header.index(name) for name in FCL_COLUMNS]
    except ValueError as missing:
        raise SystemExit(f"readme_tables: the self-CCD table has no column {missing}")
    line = lambda row: "| " + " | ".join(row[k] for k in keep) + " |"
    return "\n".join([line(header), "|" + "---|" * len(keep)] + [line(cells(row)) for row in table[2:]])


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    folder = pathlib.Path(sys.argv[1])
    read = lambda name: (folder / name).read_text().splitlines()
    for name, block in (("demo", demo(read("demo_bunnies.md"))), ("paper", paper(read("bench.md"))),
                        ("fcl", fcl(read("bench_self_ccd.md")))):
        print(f"<!-- table: {name} -->\n{block}\n")


if __name__ == "__main__":
    main()
