#!/usr/bin/env python3
"""Replace a generated table block in appear.h by the file given:
    python3 tests/gen/splice.py build/albedo_tables.h        (tests/gen/gen_albedo.c)
    python3 tests/gen/splice.py build/coat_albedo_tables.h   (tests/gen/gen_coat_albedo.c)
    python3 tests/gen/splice.py build/materials_tables.h     (tests/gen/gen_materials.c)
    python3 tests/gen/splice.py build/coated_escape_tables.h (tests/gen/gen_coated_escape.c)
    python3 tests/gen/splice.py build/aniso_albedo_tables.h  (tests/gen/gen_aniso_albedo.c)
    python3 tests/gen/splice.py build/aniso_dielectric_tables.h (tests/gen/gen_aniso_dielectric.c)
The block is chosen by the file's first line, /* BEGIN GENERATED <NAME> TABLES ...,
and runs in appear.h from that line through /* END GENERATED <NAME> TABLES */.
NAME is one of BLOCKS. The blocks live in the trailing generated part of the
header, SECTION tables (its banner ">>tables  SECTION tables", closed by
"END SECTION tables"), next to their hand-written accessors and lookups; the
splice checks that the block is there, once."""
import re
import sys
BLOCKS = ('ALBEDO', 'COAT ALBEDO', 'MATERIALS', 'COATED ESCAPE', 'ANISO ALBEDO', 'ANISO DIELECTRIC')
# gen_albedo.c, gen_coat_albedo.c, gen_materials.c, gen_coated_escape.c, gen_aniso_albedo.c,
# gen_aniso_dielectric.c
src = open('appear.h').read()
new = open(sys.argv[1]).read()
m = re.match(r'/\* BEGIN GENERATED ([A-Z ]+?) TABLES', new)
assert m and m.group(1) in BLOCKS, 'not a generated table block (first line /* BEGIN GENERATED ...)'
BEGIN = '/* BEGIN GENERATED %s TABLES' % m.group(1)
END = '/* END GENERATED %s TABLES */\n' % m.group(1)
assert new.endswith(END) and new.count(BEGIN) == 1, 'not a complete generator output'
start = src.index(BEGIN)
end = src.index(END, start) + len(END)
part, part_end = src.index('>>tables  SECTION tables'), src.index('/* END SECTION tables */')
assert src.count(BEGIN) == 1 and part < start < end <= part_end, \
    'the generated block is not (only) inside SECTION tables of appear.h'
open('appear.h', 'w').write(src[:start] + new + src[end:])
