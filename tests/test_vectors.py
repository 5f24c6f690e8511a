"""simulator.scene.vectors: the fast cross product is the cross product."""

import numpy as np

from simulator.scene.vectors import cross3


def test_cross3_is_the_cross_product():
    """Same values as np.cross (the same products, component by component),
    broadcasting like it; e_x × e_y = e_z and a × a = 0."""
    rng = np.random.default_rng(3)
    a = rng.normal(size=(50, 4, 3))
    b = rng.normal(size=(4, 3))
    assert np.allclose(cross3(a, b), np.cross(a, b), rtol=0, atol=1e-15)
    assert np.array_equal(cross3([1.0, 0, 0], [0, 1.0, 0]), [0, 0, 1.0])
    assert np.allclose(cross3(a, a), 0.0, atol=0)
