#!/usr/bin/env python3
"""Checks that the code shown in README.md and doc/*.md is the code that is built.

A Markdown file marks a code block as a copy of parts of a source file with a
comment on the line before the block's fence:

    <!-- snippet: examples/cgal_surface_mesh.cpp#includes examples/cgal_surface_mesh.cpp#parameterize -->
    ```cpp
    ...
    ```

Each FILE#NAME is the text between the two lines `// [NAME]` of FILE,
without the indentation its lines share; the block must be these parts in
order, separated by one empty line.

It also checks that every `diffuv` command of scripts/readme_images.sh (the
lines `run "$diffuv" ARGS`, which make the pictures) is written in README.md
or doc/*.md as `diffuv ARGS`, so that the text next to a picture states the
command that made it. Usage: check_snippets.py [ROOT] (CTest 'snippets').
Exit status 1, with a diff or the command, when something differs.
"""
import difflib
import glob
import os
import re
import sys

MARK = re.compile(r"^<!-- snippet: (.+?) -->\s*$")
REF = re.compile(r"([^\s#]+)#([^\s#]+)")


def region(root, path, name):
    with open(os.path.join(root, path), encoding="utf-8") as f:
        lines = f.read().split("\n")
    marks = [i for i, line in enumerate(lines) if line.strip() == "// [" + name + "]"]
    if len(marks) != 2:
        raise ValueError(f"{path}: {len(marks)} lines '// [{name}]', 2 expected")
    part = lines[marks[0] + 1:marks[1]]
    indent = min((len(l) - len(l.lstrip(" ")) for l in part if l.strip()), default=0)
    return [l[indent:] for l in part]


def check(root, md):
    errors = []
    with open(os.path.join(root, md), encoding="utf-8") as f:
        lines = f.read().split("\n")
    count = 0
    for i, line in enumerate(lines):
        m = MARK.match(line)
        if not m:
            continue
        count += 1
        where = f"{md}:{i + 1}"
        if i + 1 >= len(lines) or not lines[i + 1].startswith("```"):
            errors.append(f"{where}: the snippet mark is not followed by a code fence")
            continue
        end = next((j for j in range(i + 2, len(lines)) if lines[j].startswith("```")), None)
        if end is None:
            errors.append(f"{where}: the code block does not end")
            continue
        shown = lines[i + 2:end]
        expected = []
        try:
            for k, (path, name) in enumerate(REF.findall(m.group(1).strip())):
                if k > 0:
                    expected.append("")
                expected += region(root, path, name)
        except (OSError, ValueError) as e:
            errors.append(f"{where}: {e}")
            continue
        if shown != expected:
            diff = "\n".join(difflib.unified_diff(expected, shown, "source", md, lineterm=""))
            errors.append(f"{where}: the code block differs from {m.group(1)}:\n{diff}")
    return count, errors


PICTURE_COMMAND = re.compile(r'^run "\$diffuv" (.+)$')


def check_picture_commands(root, files):
    """Each `diffuv ...` command of scripts/readme_images.sh is written, as it
    runs, in README.md or doc/*.md (between backticks, line breaks as spaces)."""
    text = ""
    for md in files:
        with open(os.path.join(root, md), encoding="utf-8") as f:
            text += " ".join(f.read().split()) + " "
    script = "scripts/readme_images.sh"
    errors, count = [], 0
    with open(os.path.join(root, script), encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            m = PICTURE_COMMAND.match(line.strip())
            if not m:
                continue
            count += 1
            command = "`diffuv " + " ".join(m.group(1).split()) + "`"
            if command not in text:
                errors.append(f"{script}:{number}: {command} is not written in README.md or doc/*.md")
    return count, errors


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
    files = ["README.md"] + sorted(os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "doc", "*.md")))
    total, errors = 0, []
    for md in files:
        n, e = check(root, md)
        total += n
        errors += e
    commands, e = check_picture_commands(root, files)
    errors += e
    for e in errors:
        print(e, file=sys.stderr)
    if errors:
        return 1
    print(f"check_snippets: {total} code blocks equal to the source they show; "
          f"the {commands} commands of scripts/readme_images.sh written as they run")
    return 0


if __name__ == "__main__":
    sys.exit(main())
