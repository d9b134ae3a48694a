#!/usr/bin/python3
"""Keeps the case file's key tables in the docs equal to the schema they are generated from.

`sheetform schema --markdown` prints every section's key table between the marker lines
"<!-- schema: NAME -->" and "<!-- end schema -->". The docs (docs/case-file.md,
docs/static-analysis.md) hold each section's table between the same markers, with hand-written
prose around them. This script rewrites the tables in place, or with --check (ctest
case_docs_schema) fails, naming the section, when a table differs, is missing or appears twice.

    scripts/update_case_docs.py [--check] [--sheetform build/sheetform]
"""
import argparse
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
DOCS = [ROOT / "docs" / "case-file.md", ROOT / "docs" / "static-analysis.md"]
BLOCK = re.compile(r"<!-- schema: (?P<name>[^>]+?) -->\n(?P<body>.*?)<!-- end schema -->\n",
                   re.S)


def generated_tables(sheetform):
    text = subprocess.run([str(sheetform), "schema", "--markdown"], check=True,
                          capture_output=True, text=True).stdout
    return {m["name"]: m["body"] for m in BLOCK.finditer(text)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true",
                        help="change nothing; fail if a table is not what the schema makes")
    parser.add_argument("--sheetform", default=str(ROOT / "build" / "sheetform"))
    args = parser.parse_args()
    tables = generated_tables(args.sheetform)
    seen = {}
    problems = []
    for doc in DOCS:
        text = doc.read_text()

        def replace(m, doc=doc):
            name = m["name"]
            if name in seen:
                problems.append(f"{doc}: section '{name}' appears twice (also in {seen[name]})")
            seen[name] = doc
            if name not in tables:
                problems.append(f"{doc}: section '{name}' is not in the schema")
                return m[0]
            if m["body"] != tables[name]:
                problems.append(f"{doc}: the table of section '{name}' differs from the schema")
            return f"<!-- schema: {name} -->\n{tables[name]}<!-- end schema -->\n"

        new_text = BLOCK.sub(replace, text)
        if not args.check and new_text != text:
            doc.write_text(new_text)
            print(f"updated {doc.relative_to(ROOT)}")
    for name in tables:
        if name not in seen:
            problems.append(f"section '{name}' has no table in the docs: add the marker lines "
                            f"'<!-- schema: {name} -->' and '<!-- end schema -->'")
    if args.check:
        for p in problems:
            print(p, file=sys.stderr)
        if problems:
            print("run scripts/update_case_docs.py to regenerate the tables", file=sys.stderr)
            return 1
        print(f"{len(tables)} key tables match the schema")
        return 0
    for p in problems:
        if "differs" not in p:
            print(p, file=sys.stderr)
    return 1 if any("differs" not in p for p in problems) else 0


if __name__ == "__main__":
    sys.exit(main())
