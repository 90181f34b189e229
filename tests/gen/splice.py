#!/usr/bin/env python3
"""Replace the generated albedo tables in appear.h (from the line
/* BEGIN GENERATED ALBEDO TABLES ... through /* END GENERATED ALBEDO TABLES */)
by the file given (the output of tests/gen/gen_albedo.c)."""
import sys
BEGIN, END = '/* BEGIN GENERATED ALBEDO TABLES', '/* END GENERATED ALBEDO TABLES */\n'
src = open('appear.h').read()
new = open(sys.argv[1]).read()
assert new.startswith(BEGIN) and new.endswith(END), 'not a complete gen_albedo output'
start = src.index(BEGIN)
end = src.index(END, start) + len(END)
open('appear.h', 'w').write(src[:start] + new + src[end:])
