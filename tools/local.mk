## tools/local.mk -- the command-line program.
bin_PROGRAMS = tools/chaplygin
tools_chaplygin_SOURCES = tools/chaplygin.c
tools_chaplygin_CFLAGS = $(AM_CFLAGS)
tools_chaplygin_LDADD = lib/libchaplygin.la $(CODE_COVERAGE_LIBS) -lm
TESTS += tools/test-cli.sh
EXTRA_DIST += tools/test-cli.sh
