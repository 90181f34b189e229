#!/usr/bin/env python3
"""tests/check_sequenced.py - random draws are sequenced in the tests.

C leaves unspecified the order in which a call's arguments (and the operands
of +, *, ...) are evaluated: f(rb_u(), rb_u()) gives gcc and clang different
inputs from the same seed, and a saved input replays differently. This check
fails on any expression that evaluates two random draws with no sequence point
between them (two arguments of one call, two operands of one operator);
&&, ||, ?:, the comma operator, declarators and statements are sequence points.

A draw is a call of one of DRAWS, or of a function whose body calls one: in
tests/robust.c every such function (its generator is global); elsewhere those
that take the generator by pointer (h_rng *, check_rng *).

usage: python3 tests/check_sequenced.py [files...]   (default: tests/*.c tests/*.h)
"""
import glob
import re
import sys

DRAWS = {"h_rand", "h_randf", "h_rand_dir", "h_adv_float", "h_adv_u", "h_adv_dir", "next64",
         "check_rand", "check__rand_dir", "rb_next"}
KEYWORDS = {"if", "while", "for", "switch", "return", "sizeof", "do", "else", "case"}
TOKEN = re.compile(r"[A-Za-z_]\w*|\d[\w.]*(?:[eEpP][+-]\d+)?|&&|\|\||->|<<=|>>=|[-+*/%&|^<>=!]=|<<|>>|\+\+|--|\S")


def strip(src):
    """comments, strings, character literals and preprocessor lines removed"""
    src = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), src, flags=re.S)
    src = re.sub(r"//[^\n]*", "", src)
    src = re.sub(r'"(\\.|[^"\\\n])*"', '""', src)
    src = re.sub(r"'(\\.|[^'\\\n])*'", "''", src)
    out, cont = [], False
    for line in src.split("\n"):
        keep = not (cont or line.lstrip().startswith("#"))
        cont = (not keep) and line.rstrip().endswith("\\")
        out.append(line if keep else "")
    return "\n".join(out)


def tokens(src):
    toks = []
    for n, line in enumerate(src.split("\n"), 1):
        toks += [(t, n) for t in TOKEN.findall(line)]
    return toks


def group(toks, i):
    """index past the bracket group that opens at toks[i]"""
    depth = 0
    while i < len(toks):
        t = toks[i][0]
        if t in "([{":
            depth += 1
        elif t in ")]}":
            depth -= 1
            if depth == 0:
                return i + 1
        i += 1
    return i


def functions(toks):
    """(name, parameter tokens, body tokens) of each function definition"""
    out, i = [], 0
    while i < len(toks):
        t = toks[i][0]
        if t == "{":
            j = group(toks, i)
            k = i - 1
            if k >= 0 and toks[k][0] == ")":
                depth, m = 0, k
                while m >= 0:
                    if toks[m][0] == ")":
                        depth += 1
                    elif toks[m][0] == "(":
                        depth -= 1
                        if depth == 0:
                            break
                    m -= 1
                if m > 0 and re.match(r"[A-Za-z_]\w*$", toks[m - 1][0]) and toks[m - 1][0] not in KEYWORDS:
                    out.append((toks[m - 1][0], toks[m:k + 1], toks[i:j]))
            i = j
        else:
            i += 1
    return out


def calls_draw(body, draws):
    return any(body[i][0] in draws and i + 1 < len(body) and body[i + 1][0] == "("
               for i in range(len(body)))


SEQ = {"&&", "||", "?", ":", ",", ";", "{", "}"}


def check(toks, draws, name, problems):
    """toks: an expression list (no enclosing bracket); reports unsequenced draws"""
    # split at sequence points of this level
    segs, cur, i = [], [], 0
    while i < len(toks):
        t = toks[i][0]
        if t in "([{":
            j = group(toks, i)
            if t == "{":
                check(toks[i + 1:j - 1], draws, name, problems)
                segs.append(cur); cur = []
            else:
                cur.append(("G", toks[i:j]))
            i = j
            continue
        if t in SEQ:
            segs.append(cur); cur = []
        else:
            cur.append(("T", toks[i]))
        i += 1
    segs.append(cur)
    for seg in segs:
        units = []  # (line, has draw) per operand unit
        k = 0
        while k < len(seg):
            kind, v = seg[k]
            if kind == "T" and k + 1 < len(seg) and seg[k + 1][0] == "G" and seg[k + 1][1][0][0] == "(" \
                    and re.match(r"[A-Za-z_]\w*$", v[0]):
                inner = seg[k + 1][1][1:-1]
                fn = v[0]
                if fn not in KEYWORDS:
                    # a call: its arguments are unsequenced with each other
                    args, cur2, m = [], [], 0
                    while m < len(inner):
                        if inner[m][0] in "([{":
                            e = group(inner, m); cur2 += inner[m:e]; m = e; continue
                        if inner[m][0] == ",":
                            args.append(cur2); cur2 = []
                        else:
                            cur2.append(inner[m])
                        m += 1
                    args.append(cur2)
                    with_draw = [a for a in args if contains_draw(a, draws)]
                    if len(with_draw) >= 2:
                        problems.append((name, v[1], "%s(...): %d arguments draw random numbers" % (fn, len(with_draw))))
                    for a in args:
                        check(a, draws, name, problems)
                else:
                    check(inner, draws, name, problems)
                units.append((v[1], fn in draws or (fn not in KEYWORDS and contains_draw(inner, draws))))
                k += 2
                continue
            if kind == "G":
                check(v[1:-1], draws, name, problems)
                units.append((v[0][1], contains_draw(v[1:-1], draws)))
            k += 1
        n = sum(1 for u in units if u[1])
        if n >= 2:
            line = [u[0] for u in units if u[1]][0]
            problems.append((name, line, "%d operands of one expression draw random numbers" % n))


def contains_draw(toks, draws):
    return any(toks[i][0] in draws and i + 1 < len(toks) and toks[i + 1][0] == "("
               for i in range(len(toks)))


def main(files):
    parsed = {f: tokens(strip(open(f).read())) for f in files}
    draws = set(DRAWS)
    fns = {f: functions(t) for f, t in parsed.items()}
    changed = True
    while changed:
        changed = False
        for f, lst in fns.items():
            global_rng = f.endswith("robust.c")
            for name, params, body in lst:
                if name in draws or not calls_draw(body, draws):
                    continue
                ptxt = " ".join(t for t, _ in params)
                if global_rng or re.search(r"\b(h_rng|check_rng)\s*\*", ptxt):
                    draws.add(name); changed = True
    problems = []
    for f, t in parsed.items():
        # each function body separately (a declaration's initialisers included)
        check(t, draws, f, problems)
    seen = set()
    for f, line, what in problems:
        if (f, line, what) in seen:
            continue
        seen.add((f, line, what))
        print("%s:%d: unsequenced random draws: %s" % (f, line, what))
    if problems:
        print("check_sequenced: %d expressions draw random numbers in an unspecified order: draw into "
              "locals first, in a fixed order" % len(seen))
        return 1
    print("check_sequenced: %d files, no unsequenced random draws (%d draw functions)" % (len(files), len(draws)))
    return 0


if __name__ == "__main__":
    fs = sys.argv[1:] or sorted(glob.glob("tests/*.c") + glob.glob("tests/*.h"))
    sys.exit(main(fs))
