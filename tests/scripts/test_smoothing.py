"""The studies' one smoothing (bin/darcydem/smoothing.py, shared by the
shear and settlement studies): a moving Hanning average keeps the series'
length, a constant, and a straight line away from the padded ends (the
window is symmetric and sums to one); an even width is taken as the next
odd one; a series shorter than the window comes back unchanged."""

import numpy as np

from darcydem.smoothing import hanning_smooth


def test_hanning_smooth_keeps_constants_and_lines():
    t = np.linspace(0.0, 1.0, 101)
    # to round-off: the weights sum to one only to a few ulp
    assert np.max(np.abs(hanning_smooth(np.full(101, 2.5), 9) - 2.5)) < 1e-14
    line = 3.0 * t - 1.0
    smooth = hanning_smooth(line, 10)   # taken as 11: 5 points padded at each end
    assert smooth.shape == line.shape
    assert np.max(np.abs(smooth[5:-5] - line[5:-5])) < 1e-14
    noisy = line + 0.1 * np.where(np.arange(101) % 2, 1.0, -1.0)   # alternating noise
    assert np.max(np.abs(hanning_smooth(noisy, 11)[5:-5] - line[5:-5])) < 0.01
    assert np.array_equal(hanning_smooth([1.0, 4.0], 5), [1.0, 4.0])
