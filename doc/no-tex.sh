#!/bin/sh
# no-tex.sh -- what `make pdf' runs in place of texi2dvi when configure
# found no TeX (configure.ac): one line saying what to install.
echo "make pdf: TeX is not installed (configure found no pdftex); install texlive-base texlive-plain-generic texlive-fonts-recommended (Debian) and run configure again" >&2
exit 1
