"""Property tests (hypothesis): d falls as e rises (and k, overlap end), k falls as T_c grows (k ~ T_c^{-5/2}),
and every broadcastable set of shapes gives the broadcast shape."""
import numpy as np
from hypothesis import assume, given, settings, strategies as st
from hypothesis.extra import numpy as hnp

import hertzdamp

positive = st.floats(1e-6, 1e2)
settings.register_profile("hertzdamp", max_examples=60, deadline=None, derandomize=True)
settings.load_profile("hertzdamp")


@given(st.lists(st.floats(0.002, 1.0), min_size=2, max_size=30, unique=True), st.floats(1e-7, 1e-3),
       st.floats(1e-9, 1.0), positive, st.sampled_from(hertzdamp.LAWS), st.sampled_from(hertzdamp.ENDS))
def test_d_falls_as_e_rises(es, tc, m, u, law, end):
    e = np.sort(np.array(es))
    assume(np.all(np.diff(e) > 1e-9 * e[1:]))
    k, d = hertzdamp.invert(e, tc, m, u, law=law, end=end)
    assert np.all(np.diff(d) < 0) or (e[-1] == 1.0 and np.all(np.diff(d[:-1]) < 0) and d[-1] == 0.0)
    if end == "overlap":   # tau_c grows with alpha (overlap end): a stiffer contact for the lower e
        assert np.all(np.diff(k) <= 0)


@given(st.lists(st.floats(1e-7, 1e-3), min_size=2, max_size=30, unique=True), st.floats(0.01, 0.99),
       st.floats(1e-9, 1.0), positive)
def test_k_falls_as_tc_grows(tcs, e, m, u):
    tc = np.sort(np.array(tcs))
    assume(np.all(np.diff(tc) > 1e-9 * tc[1:]))
    k, d = hertzdamp.invert(e, tc, m, u)
    assert np.all(np.diff(k) < 0)
    assert np.allclose(k * tc ** 2.5, k[0] * tc[0] ** 2.5, rtol=1e-13)


@given(hnp.mutually_broadcastable_shapes(num_shapes=4, min_dims=0, max_dims=3, max_side=4))
def test_the_broadcast_shape(shapes):
    e, tc, m, u = (np.full(s, v) for s, v in zip(shapes.input_shapes, (0.7, 1e-5, 1e-6, 1.0)))
    k, d = hertzdamp.invert(e, tc, m, u)
    assert np.shape(k) == np.shape(d) == shapes.result_shape
    k0, _ = hertzdamp.invert(0.7, 1e-5, 1e-6, 1.0)
    assert np.all(np.asarray(k) == k0)
    e2, tc2 = hertzdamp.forward(k, d, m, u)
    assert np.shape(e2) == shapes.result_shape
