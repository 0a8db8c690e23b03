## doc/local.mk -- the Texinfo manual, the concordance and the errata.
info_TEXINFOS = doc/chaplygin.texi
doc_chaplygin_TEXINFOS = doc/notation.texi doc/conventions.texi \
	doc/methods.texi doc/concordance.texi doc/errata.texi doc/api.texi \
	doc/accuracy.texi doc/figures.texi doc/bench.texi doc/bench-table.texi
# the figures of `make figures' (tools/local.mk), committed
EXTRA_DIST += doc/figures/fig2a.png doc/figures/fig2b.png \
	doc/figures/fig3.png doc/figures/fig4.png doc/figures/fig5.png \
	doc/figures/fig6.png doc/figures/fig7.png doc/figures/fig8.png \
	doc/figures/fig9.png doc/figures/fig10.png
# the work-precision diagram of `make bench' (bench/local.mk), committed
EXTRA_DIST += doc/figures/work-precision.png
dist_doc_DATA = doc/concordance.tsv
