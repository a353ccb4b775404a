"""Percentile interpolation: the two-piece normal model of spec §2.

From the stored 5th/50th/95th percentile values of a measurement,
    v(p) = v50 + z(p) * s,   s = (v50 - v5)/z95 below the median, (v95 - v50)/z95 above,
where z(p) is the standard normal quantile and z95 = z(95) = 1.64485...  The
inverse uses the same pieces.  Everything works on numpy arrays whose last
axis holds (v5, v50, v95); rows may run either way (a lower joint limit grows
more negative with the percentile).
"""

from __future__ import annotations

from statistics import NormalDist

import numpy as np
import numpy.typing as npt

from sass_tui.model.errors import SassError

MIN_PERCENTILE = 0.5
MAX_PERCENTILE = 99.5
_STANDARD = NormalDist()
# The spec writes 1.6449; the exact quantile keeps v(5) and v(95) equal to the
# stored values to the last bit instead of to 1e-5.
Z95 = _STANDARD.inv_cdf(0.95)
_ppf = np.frompyfunc(_STANDARD.inv_cdf, 1, 1)
_cdf = np.frompyfunc(_STANDARD.cdf, 1, 1)


class PercentileError(ValueError, SassError):
    """A percentile outside 0.5-99.5, or not a number."""


def check_percentile(p: npt.ArrayLike) -> npt.ArrayLike:
    arr = np.asarray(p, dtype=float)
    bad = ~((arr >= MIN_PERCENTILE) & (arr <= MAX_PERCENTILE))
    if np.any(bad):
        first = arr[bad].flat[0] if arr.ndim else float(arr)
        raise PercentileError(
            f"percentile {first:g} is outside {MIN_PERCENTILE:g}-{MAX_PERCENTILE:g}"
        )
    return p


def z_score(p: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Standard normal quantile of percentile(s) p (0.5-99.5)."""
    arr = np.asarray(p, dtype=float)
    if arr.ndim == 0:
        return np.float64(_STANDARD.inv_cdf(float(arr) / 100.0))
    return np.asarray(_ppf(arr / 100.0), dtype=float)


def value_at(stats: npt.NDArray[np.float64], p: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Values at percentile p.  stats[..., 0:3] = (v5, v50, v95); p broadcasts
    against stats[..., 0].  NaN (no value) stays NaN."""
    check_percentile(p)
    v5, v50, v95 = stats[..., 0], stats[..., 1], stats[..., 2]
    p = np.asarray(p, dtype=float)
    z = z_score(p)
    spread = np.where(z < 0, v50 - v5, v95 - v50) / Z95
    out = v50 + z * spread
    # Exact at the stored percentiles, whatever rounding the arithmetic does.
    out = np.where(p == 5.0, v5, out)
    out = np.where(p == 50.0, v50, out)
    return np.where(p == 95.0, v95, out)


def percentile_of(
    stats: npt.NDArray[np.float64], value: npt.ArrayLike
) -> npt.NDArray[np.float64] | np.float64:
    """Percentile of value(s) against stats (the inverse of value_at).

    The result is not clipped to 0.5-99.5: a real person can lie outside it.
    NaN where it is undefined: no stored value, or a degenerate row (all three
    equal) with a value other than that one.  A degenerate row's own value is
    at the 50th percentile.
    """
    v5, v50, v95 = stats[..., 0], stats[..., 1], stats[..., 2]
    value = np.asarray(value, dtype=float)
    diff = value - v50
    lower, upper = (v50 - v5) / Z95, (v95 - v50) / Z95
    with np.errstate(divide="ignore", invalid="ignore"):
        z_lower = diff / lower
        z_upper = diff / upper
    # Take the piece on which the value lies: z <= 0 on the lower, z >= 0 on the
    # upper piece.  Either can serve a non-monotonic row; prefer the lower.
    z = np.where(
        np.isfinite(z_lower) & (z_lower <= 0),
        z_lower,
        np.where(np.isfinite(z_upper) & (z_upper >= 0), z_upper, np.nan),
    )
    z = np.where(diff == 0, 0.0, z)
    z = np.where(np.isnan(v50) | np.isnan(value), np.nan, z)
    flat = np.atleast_1d(z).astype(float)
    out = np.full(flat.shape, np.nan)
    ok = np.isfinite(flat)
    if ok.any():
        out[ok] = _cdf(flat[ok]).astype(float) * 100.0
    out = out.reshape(np.shape(z))
    # Exact at the stored percentiles.
    out = np.where((value == v5) & (v5 != v50), 5.0, out)
    out = np.where((value == v95) & (v95 != v50), 95.0, out)
    return out if out.ndim else np.float64(out)
