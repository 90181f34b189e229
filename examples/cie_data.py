#!/usr/bin/env python3
"""Writes examples/cie_data.h (the tracer's spectral colour data) from tests/gen/materials_data.h:
the CIE 1931 2-degree observer every 5 nm (its 1 nm rows at 360, 365, ..., 830 nm) and D65.

    python3 examples/cie_data.py > examples/cie_data.h
"""
import os
import re

HEAD = """\
/* examples/cie_data.h - the colour data of the tracer's spectral mode (examples/tracer.c):
   the CIE 1931 2-degree standard observer (xbar, ybar, zbar) and the CIE standard illuminant
   D65 (relative spectral power), both at 5 nm from 360 to 830 nm (95 rows), read linearly
   between rows.
     observer  CIE 018:2019 / ISO/CIE 11664-1:2019 (the 1 nm table of CIE 15:2004, here its
               rows at 360, 365, ..., 830 nm: the CIE's own 5 nm table has the same values)
     D65       ISO/CIE 11664-2:2022 (CIE S 014-2), the 5 nm table of CIE 15:2004
   Copied from tests/gen/materials_data.h, the transcription that appear.h's RGB forms of the
   metals (appear_metal_to_rgb) are integrated from at 1 nm, by
       python3 examples/cie_data.py > examples/cie_data.h
   Not in appear.h: the header needs colour only inside its generated RGB forms; a renderer
   has its own observer and illuminant tables. */
#ifndef TRACER_CIE_DATA_H
#define TRACER_CIE_DATA_H

#define CIE_LAMBDA_MIN 360.0f /* nm, the first row */
#define CIE_LAMBDA_STEP 5.0f  /* nm between rows */
#define CIE_N 95
"""


def block(src, name):
    """the text between the braces of the array `name`"""
    s = src[src.index(name):]
    s = s[s.index("= {") + 3:]
    return s[:s.index("};")]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    src = open(os.path.join(here, "..", "tests", "gen", "materials_data.h")).read()
    num = r"([-0-9.eE+]+)"
    cmf = re.findall(r"\{\s*%s,\s*%s,\s*%s\s*\}" % (num, num, num), block(src, "md_cmf[MD_CMF_N]"))
    d65 = [v.strip() for v in block(src, "md_d65[MD_D65_N]").split(",") if v.strip()]
    assert len(cmf) == 471 and len(d65) == 95
    out = [HEAD, "static const float cie_cmf_5nm[CIE_N][3] = {"]
    for i in range(0, 471, 5):
        row = "    { %sf, %sf, %sf }," % cmf[i]
        out.append(row + (" /* %d nm */" % (360 + i) if i % 50 == 0 else ""))
    out += ["};", "static const float cie_d65_5nm[CIE_N] = {"]
    line = "   "
    for v in d65:
        item = " %sf," % v
        if len(line) + len(item) > 100:
            out.append(line)
            line = "   "
        line += item
    out += [line, "};", "", "#endif"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
