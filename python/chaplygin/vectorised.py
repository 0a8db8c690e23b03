"""How the functions of chaplygin take NumPy arrays.

Any input of any function may be an array (or anything numpy.asarray
takes): the inputs are broadcast together as NumPy broadcasts, and one C
loop (generated from <chaplygin.h> by python/gen.py) calls the C function
once per element of the broadcast shape, without a Python loop.  Scalars
alone take a fast path that calls the C function once.

Shapes.  An input that is one number in C is an array of any shape; one
that is an array of N numbers in C (q[4], peg[2]) is an array of shape
(..., N); one that is a struct (DiscreteState, Discrete, ...) is a
structured array of the class's dtype (or a dict of its fields, arrays
broadcast, missing ones 0), or one object, used for every element.  Each
output gains the broadcast shape: a number becomes an array of that shape,
an array of N numbers one of shape (..., N) (J[16]: (..., 4, 4)), a struct a
structured array of its dtype (chaplygin.as_columns splits one into a dict
of plain arrays).  The results are exactly those of the scalar calls, bit
for bit.

Types.  Real inputs are converted to float64 from numbers (numbers.Real
and decimal.Decimal); None, text, bytes and other objects, also inside
lists and object arrays, are a TypeError (not NaN, not a parsed number);
integer inputs (dir, reversal, n, request) must be integers (an array of
floats is a TypeError, a value outside the C type an OverflowError).
Masked arrays (numpy.ma) are a TypeError: their mask would be lost; pass
x.filled(np.nan) or x.compressed().  Non-contiguous, strided,
broadcast and read-only arrays are read in place where one stride fits and
copied otherwise; nothing is written into an input.

Failures (the errors keyword).  Each element has its own status.
  errors='raise' (default): if any element fails, the exception of the
    first failing element's status is raised (DomainError, SpinError, ...),
    with statuses (the array of statuses), index (the first failing index)
    and partial (the results, see below) as attributes.
  errors='return': no exception for a status; the result is a named tuple
    of the outputs and status, the array of statuses (0 = success).
Where an element failed its outputs are NaN (float fields) and 0 (integer
fields): the library writes nothing on failure, and the status says which
elements those are.  Outputs that the library writes only when a flag is
set (smooth.reversal's Sc when reverses, discrete.collisions_before_reversal's
n, discrete.stability_boundary's ymin, the turning points Dc beyond n_real)
are NaN or 0 where the flag says so, and None in a scalar call.  NaN is
never returned without a status or a flag that says why.

Speed.  The per-element cost is that of the C function plus a few
nanoseconds (python/bench/bench.py measures it against the same loop in C).
The C loop runs without the GIL.
"""
