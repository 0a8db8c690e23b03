## doc/local.mk -- the Texinfo manual, the concordance and the errata.
info_TEXINFOS = doc/chaplygin.texi
doc_chaplygin_TEXINFOS = doc/notation.texi doc/conventions.texi \
	doc/methods.texi doc/concordance.texi doc/errata.texi doc/api.texi \
	doc/accuracy.texi
dist_doc_DATA = doc/concordance.tsv
