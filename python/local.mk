## python/local.mk -- the Python package chaplygin (configure
## --enable-python, on by default when Python 3 with NumPy, cffi and
## Python.h is found).
##
## python/gen.py reads lib/chaplygin.h and writes the extension module's C
## source (cffi in API mode), one C loop per function (the vectorised
## path) and the Python wrappers; libtool links the module against
## lib/libchaplygin.la (relinked against the installed library by `make
## install').  In the build tree the package is python/chaplygin
## (PYTHONPATH=$(abs_top_builddir)/python); `make install' puts it into
## $(pyexecdir)/chaplygin.  `make check' runs python/tests with pytest.

PY_PACKAGE = python/chaplygin/__init__.py python/chaplygin/_core.py \
	python/chaplygin/_groups.py python/chaplygin/discrete.py \
	python/chaplygin/smooth.py python/chaplygin/massless.py \
	python/chaplygin/printed.py python/chaplygin/sweep.py \
	python/chaplygin/scene.py python/chaplygin/vectorised.py \
	python/chaplygin/equation.py python/chaplygin/certified.py \
	python/chaplygin/dataset.py
PY_TESTS = python/tests/conftest.py \
	python/tests/test_reachable.py python/tests/test_values.py \
	python/tests/test_eq.py python/tests/test_errors.py \
	python/tests/test_vectorised.py python/tests/test_robust.py \
	python/tests/test_scene.py python/tests/test_orbit.py \
	python/tests/test_docs.py python/tests/test_smooth_path.py \
	python/tests/test_equation.py python/tests/test_locale.py \
	python/tests/test_interrupt.py python/tests/test_pickle.py \
	python/tests/test_types.py python/tests/test_gen_write.py \
	python/tests/test_certified.py python/tests/test_atlas.py
PY_GENERATED = python/gen/module.c python/gen/vec.c python/gen/vec.h \
	python/chaplygin/_generated.py
EXTRA_DIST += python/gen.py python/README $(PY_PACKAGE) \
	$(PY_TESTS) \
	python/tests/run-pytest.in python/tests/cvalues.c \
	python/src/chp_python.h python/src/orbit.c python/src/basins.c \
	python/src/scene_api.c python/src/atlas.c python/src/poll.h \
	python/src/poll.c python/bench/bench.py python/bench/cbench.c \
	python/examples/fig2a.py python/examples/fig3.py

if ENABLE_PYTHON
# pkgpyexecdir: AM_PATH_PYTHON's $(pyexecdir)/chaplygin.  A directory name
# without '_' matters: automake 1.16.5 orders install-DIRLTLIBRARIES after
# install-libLTLIBRARIES (libtool relinks the module against the installed
# libchaplygin-scene) under the name with the '_' dropped, so a
# chaplygin_pyexec directory went unordered and a parallel `make install'
# failed: "cannot find -lchaplygin-scene".
pkgpyexec_PYTHON = $(PY_PACKAGE)
nodist_pkgpyexec_PYTHON = python/chaplygin/_generated.py

# The extension module: cffi's C (warnings are cffi's business, not ours:
# no WARN_CFLAGS) over a convenience library of our C (with them).
pkgpyexec_LTLIBRARIES = python/chaplygin/_chaplygin_cffi.la
nodist_python_chaplygin__chaplygin_cffi_la_SOURCES = python/gen/module.c
python_chaplygin__chaplygin_cffi_la_CPPFLAGS = $(AM_CPPFLAGS) \
	-I$(srcdir)/python/src -I$(srcdir)/lib/scene -Ipython/gen \
	$(PYTHON_CPPFLAGS)
python_chaplygin__chaplygin_cffi_la_CFLAGS = $(CODE_COVERAGE_CFLAGS)
python_chaplygin__chaplygin_cffi_la_LDFLAGS = -module -avoid-version \
	-shared -export-symbols-regex '^PyInit__chaplygin_cffi$$' \
	$(OPENMP_CFLAGS)
python_chaplygin__chaplygin_cffi_la_LIBADD = python/libchp-py.la \
	lib/libchaplygin-scene.la lib/libchaplygin.la $(GSL_LIBS) \
	$(CODE_COVERAGE_LIBS) -lm

# Our C: the generated loops, the orbits, basins point by point, the
# columns of a scene run by the scene engine (lib/scene/, through its
# public header), and the poll of every loop (Ctrl-C).
noinst_LTLIBRARIES += python/libchp-py.la
python_libchp_py_la_SOURCES = python/src/chp_python.h python/src/orbit.c \
	python/src/basins.c python/src/scene_api.c python/src/atlas.c \
	python/src/poll.h python/src/poll.c
nodist_python_libchp_py_la_SOURCES = python/gen/vec.c python/gen/vec.h
python_libchp_py_la_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/python/src \
	-I$(srcdir)/lib/scene -Ipython/gen
python_libchp_py_la_CFLAGS = $(AM_CFLAGS) $(GSL_CFLAGS)

python/gen.stamp: $(srcdir)/lib/chaplygin.h $(srcdir)/python/gen.py \
		$(srcdir)/python/src/chp_python.h \
		$(srcdir)/lib/scene/chaplygin-scene.h
	$(AM_V_GEN)$(MKDIR_P) python/gen python/chaplygin \
	  && $(PYTHON) $(srcdir)/python/gen.py $(srcdir)/lib/chaplygin.h \
	    $(srcdir)/lib/scene/chaplygin-scene.h,$(srcdir)/python/src/chp_python.h \
	    python/gen \
	    python/chaplygin/_generated.py $(PACKAGE_VERSION) >/dev/null \
	  && touch $@
$(PY_GENERATED): python/gen.stamp
$(python_chaplygin__chaplygin_cffi_la_OBJECTS) \
$(python_libchp_py_la_OBJECTS): python/gen.stamp

# The package in the build tree: the module beside the Python files
# (copied there in a VPATH build).
python/chaplygin/_chaplygin_cffi.so: python/chaplygin/_chaplygin_cffi.la
	$(AM_V_GEN)rm -f $@ && cp python/chaplygin/.libs/_chaplygin_cffi.so $@
python/stage.stamp: $(PY_PACKAGE)
	$(AM_V_GEN)if test "$(srcdir)" != .; then \
	  $(MKDIR_P) python/chaplygin && for f in $(PY_PACKAGE); do \
	    cp $(srcdir)/$$f $$f || exit 1; done; fi; touch $@
all-local: python/stage.stamp python/chaplygin/_chaplygin_cffi.so

# The tests: pytest (TAP through python/tests/tap.py), with the C values
# they compare against from python/tests/cvalues.
check_PROGRAMS += python/tests/cvalues
python_tests_cvalues_SOURCES = python/tests/cvalues.c
python_tests_cvalues_CPPFLAGS = $(AM_CPPFLAGS) -I$(srcdir)/tests
python_tests_cvalues_LDADD = lib/libchaplygin.la $(CODE_COVERAGE_LIBS) -lm
check_SCRIPTS = python/run-pytest
python/run-pytest: $(srcdir)/python/tests/run-pytest.in Makefile
	$(AM_V_GEN)sed -e 's|@PYTHON[@]|$(PYTHON)|g' \
	  -e 's|@HAVE_PYTEST[@]|$(HAVE_PYTEST)|g' \
	  -e 's|@abs_top_srcdir[@]|$(abs_top_srcdir)|g' \
	  $(srcdir)/python/tests/run-pytest.in > $@.tmp \
	  && chmod +x $@.tmp && mv $@.tmp $@
TESTS += python/run-pytest

# `make bench-python': the speed of the vectorised and scalar calls
# against the same work in C (python/bench/bench.py), this machine.
noinst_PROGRAMS += python/bench/cbench
python_bench_cbench_SOURCES = python/bench/cbench.c
python_bench_cbench_LDADD = lib/libchaplygin.la -lm
PY_INSTALLCHECK = installcheck-python
PY_ENABLED = yes
else
PY_INSTALLCHECK =
PY_ENABLED = no
endif

bench-python: all
	@if test $(PY_ENABLED) != yes; then \
	  echo "bench-python: configure did not enable Python ($(PYTHON_WHY))" >&2; \
	  exit 1; fi
	$(MAKE) $(AM_MAKEFLAGS) python/bench/cbench
	PYTHONPATH=$(abs_top_builddir)/python $(PYTHON) \
	  $(srcdir)/python/bench/bench.py --cbench python/bench/cbench

# A check of the installed package: imported from the installation alone.
installcheck-local: $(PY_INSTALLCHECK)
installcheck-python:
	cd / && PYTHONPATH='$(DESTDIR)$(pyexecdir)' $(PYTHON) -c \
	  'import chaplygin, sys; \
	   assert chaplygin.__file__.startswith(sys.argv[1]), chaplygin.__file__; \
	   s = chaplygin.discrete.sigma4(1, 1/3, dir=1); \
	   assert abs(s - 21/25) <= 2 * 2**-52 * 21/25, s; print("python:", s)' \
	  '$(DESTDIR)$(pyexecdir)'
.PHONY: bench-python installcheck-python

HAVE_PYTEST = @have_pytest@
PYTHON_WHY = @python_why@
CLEANFILES += $(PY_GENERATED) python/gen.stamp python/stage.stamp \
	python/chaplygin/_chaplygin_cffi.so python/run-pytest
clean-local: python-clean
python-clean:
	-rm -rf python/chaplygin/__pycache__ python/tests/__pycache__ \
	  python/.pytest_cache
	-if test "$(srcdir)" != .; then rm -f $(PY_PACKAGE); fi
.PHONY: python-clean
