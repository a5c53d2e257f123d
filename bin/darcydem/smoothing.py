"""Smoothing of measured time series, shared by the studies (shear,
settlement) so that their curves are smoothed the same way."""

import numpy as np


def hanning_smooth(y, width):
    """Moving Hanning-window average over an odd width of at least 3
    points (the shear paper's smoothing of its Figs 4, 7), ends padded with
    the end values so that the result has y's length; y unchanged when it
    is shorter than the window."""
    y = np.asarray(y, dtype=float)
    width = max(3, int(width) | 1)
    if len(y) < width:
        return y
    w = np.hanning(width + 2)[1:-1]
    w /= w.sum()
    padded = np.concatenate([np.full(width // 2, y[0]), y, np.full(width // 2, y[-1])])
    return np.convolve(padded, w, mode="valid")
