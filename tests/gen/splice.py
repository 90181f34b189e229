#!/usr/bin/env python3
"""Replace the body of the multiscatter section of appear.h by the files given (concatenated)."""
import sys
src = open('appear.h').read()
start = src.index('/* SECTION multiple scattering, energy compensation, thin film')
start = src.index('*/\n', src.index('/* ====', start)) + 3
end = src.index('/* END SECTION multiscatter */')
body = ''.join(open(f).read() for f in sys.argv[1:])
open('appear.h', 'w').write(src[:start] + body + src[end:])
