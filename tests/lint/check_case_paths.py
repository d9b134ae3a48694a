#!/usr/bin/env python3
"""Fails if a case file refers to a path outside the repository (ctest case_paths, label lint).

Every cases/**/*.toml, cases/**/*.geo and cases/**/README.md is read. A path is refused when it
is absolute (/work/shared/..., /home/..., ~/...; a scratch folder under /tmp/ in a command example
is fine) or relative and leads out of the repository from the file's folder (../../../x), or
relative and names nothing in the repository (a typo, a moved file). A mention of REFERENCES.md (the name of a reference list kept
outside the repository) is refused too: benchmark data is cited from the project's own
docs/references.md. Paths inside the repository (../../docs/references.md, ../square_cup_aluminium)
are fine.

    tests/lint/check_case_paths.py [REPO_ROOT]
"""
import os
import re
import sys

# An absolute path: a slash not preceded by a word character, a dot or a closing bracket (so units
# such as N/mm or 1/s do not count), then at least one folder: /work/x, (/home/a/b.md, "~/x".
ABSOLUTE = re.compile(r"(?<![\w.)\]}/])(~?/(?:[\w.-]+/)+[\w.-]*)")
# A relative path that climbs: one or more ../ then a name.
RELATIVE = re.compile(r"(?<![\w/.])((?:\.\./)+[\w.-]*(?:/[\w.-]+)*)")
FOREIGN_NAME = re.compile(r"\bREFERENCES\.md\b")


def problems(root, path):
    folder = os.path.dirname(path)
    found = []
    with open(path, encoding="utf-8", errors="replace") as f:
        for number, line in enumerate(f, 1):
            for match in ABSOLUTE.finditer(line):
                if not match.group(1).startswith("/tmp/"):  # scratch output in a command example
                    found.append((number, match.group(1), "an absolute path"))
            for match in RELATIVE.finditer(line):
                target = os.path.normpath(os.path.join(folder, match.group(1)))
                if os.path.relpath(target, root).startswith(".."):
                    found.append((number, match.group(1), "a path outside the repository"))
                elif not os.path.exists(target):
                    found.append((number, match.group(1), "no such file or folder in the repository"))
            for match in FOREIGN_NAME.finditer(line):
                found.append((number, match.group(0),
                              "a reference list outside the repository (cite docs/references.md)"))
    return found


def main():
    root = os.path.realpath(sys.argv[1] if len(sys.argv) > 1
                            else os.path.join(os.path.dirname(__file__), "..", ".."))
    cases = os.path.join(root, "cases")
    checked = 0
    failures = []
    for folder, dirs, files in os.walk(cases):
        dirs[:] = sorted(d for d in dirs if d != "results")  # run output, not case input
        for name in sorted(files):
            if not (name.endswith(".toml") or name.endswith(".geo") or name == "README.md"):
                continue
            path = os.path.join(folder, name)
            checked += 1
            for number, text, why in problems(root, path):
                failures.append(f"{os.path.relpath(path, root)}:{number}: {text}: {why}")
    for failure in failures:
        print(failure)
    if checked == 0:
        print(f"no case files found under {cases}")
        return 1
    print(f"{checked} case files checked, {len(failures)} references outside the repository")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
