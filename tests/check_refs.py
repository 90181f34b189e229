#!/usr/bin/env python3
"""tests/check_refs.py - the citation keys of appear.h against its one REFERENCES list.

    python3 tests/check_refs.py [appear.h]        (make check-refs; in make test)

A citation is a bracket group whose comma- or semicolon-separated pieces start
with a key: [Walter07], [Heitz16, Sec. 5.3; Veach97, Sec. 5.2], [Cramer78,
Novak14 Sec. 3]. A key is a capitalised name and two digits of the year, with
an optional letter: Heitz14, HdE14, ONeill14, Heitz16b. The list is the block
that opens with the line "REFERENCES (the one list" in the documentation at
the top; an entry is a line "   [Key]  authors. title. venue, year.".
Checked:
  - every key cited anywhere in the file is defined in the list exactly once;
  - every key of the list is cited outside the list and the CONTENTS block
    (that is, at the code or the part documentation that uses the paper);
  - no line outside the list looks like an entry (a second, scattered list);
  - no paper is cited by "Author et al. 20xx" instead of its key.
Prints one line per problem and exits 1 if there is any, else prints a summary.
"""
import re
import sys

KEY = re.compile(r"[A-Z][A-Za-z'-]*[0-9]{2}[a-z]?$")
KEY_START = re.compile(r"\s*([A-Z][A-Za-z'-]*[0-9]{2}[a-z]?)\b")
ENTRY = re.compile(r"^   \[([^\]]+)\]\s+\S")
STRAY_ENTRY = re.compile(r"^\s*\[([A-Z][A-Za-z'-]*[0-9]{2}[a-z]?)\]\s{2,}[A-Z]")
ET_AL = re.compile(r"\bet al\.?,?\s+(19|20)[0-9]{2}\b")
RULE = re.compile(r"^\s*={20,}\s*$")


def block(lines, title):
    """[first, last) line indices of the documentation block titled `title`:
    from its header's closing rule to the next rule (the next block's)."""
    for i, line in enumerate(lines):
        if line.strip().startswith(title):
            j = i + 1
            while j < len(lines) and not RULE.match(lines[j]):
                j += 1
            k = j + 1
            while k < len(lines) and not RULE.match(lines[k]):
                k += 1
            return j + 1, k
    return None


def citations(text):
    """(key, offset) for every key that opens a piece of a bracket group."""
    out = []
    for m in re.finditer(r"\[([^\[\]]{0,300})\]", text):
        for piece in re.split(r"[,;]", m.group(1)):
            k = KEY_START.match(piece)
            if k and (k.end() == len(piece) or not piece[k.end()].isalnum()):
                out.append((k.group(1), m.start()))
    return out


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "appear.h"
    src = open(path, encoding="utf-8").read()
    lines = src.split("\n")
    errors = []
    refs = block(lines, "REFERENCES (the one list")
    contents = block(lines, "CONTENTS")
    if refs is None:
        print("%s: no REFERENCES (the one list ...) block" % path)
        return 1
    r0, r1 = refs
    c0, c1 = contents if contents else (0, 0)

    defined = {}
    for i in range(r0, r1):
        m = ENTRY.match(lines[i])
        if m:
            key = m.group(1)
            if not KEY.match(key):
                errors.append("%s:%d: [%s] is not a key (Name and two digits of the year)"
                              % (path, i + 1, key))
            defined.setdefault(key, []).append(i + 1)
    for key, where in sorted(defined.items()):
        if len(where) > 1:
            errors.append("%s: [%s] defined %d times in the list (lines %s)"
                          % (path, key, len(where), ", ".join(map(str, where))))

    line_of = []
    for i, line in enumerate(lines):
        line_of.extend([i] * (len(line) + 1))
    cited_outside = {}
    for key, off in citations(src):
        i = line_of[off]
        if r0 <= i < r1:
            continue  # a citation inside an entry (e.g. "after [Hoffman19]")
        if key not in defined:
            errors.append("%s:%d: [%s] cited but not in the REFERENCES list" % (path, i + 1, key))
        if not (c0 <= i < c1):
            cited_outside[key] = cited_outside.get(key, 0) + 1
    for key in sorted(defined):
        if key not in cited_outside:
            errors.append("%s:%d: [%s] is in the list but cited nowhere outside it and CONTENTS"
                          % (path, defined[key][0], key))

    for i, line in enumerate(lines):
        if r0 <= i < r1:
            continue
        m = STRAY_ENTRY.match(line)
        if m:
            errors.append("%s:%d: looks like a reference entry outside the one list: %s"
                          % (path, i + 1, line.strip()))
        if ET_AL.search(line):
            errors.append("%s:%d: cite the paper by its key, not \"et al. <year>\": %s"
                          % (path, i + 1, line.strip()))

    for e in errors:
        print(e)
    if errors:
        print("check_refs: %d problem(s)" % len(errors))
        return 1
    print("check_refs: %d keys, each defined once and cited (%d citations outside the list)"
          % (len(defined), sum(cited_outside.values())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
