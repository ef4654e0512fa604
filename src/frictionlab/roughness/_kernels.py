"""Hot loops of the lattice-spring model: compiled (numba) kernels and their NumPy twins.

Private module. :mod:`frictionlab.roughness.lattice` calls one time sample at a time:

* :func:`multipliers_nb` / :func:`multipliers_np`: the global force multiplier
  ``H(mu0, g, beta)`` (frame-free form of Eqs 1-4) for many gradients;
* :func:`solve_offset_nb` / :func:`solve_offset_np`: the load balance for the offset
  ``c = l0 - d``, with compressive stiffness ``k_c`` and tensile stiffness ``k_t``
  (``k_t = 0``: no adhesion);
* :func:`solve_offset_detach_nb` / :func:`solve_offset_detach_np`: the load balance when
  stretched springs detach beyond a cut-off elongation (option, off by default): the
  largest root of a non-monotone balance;
* :func:`sample_into_nb` (caller's buffers) / :func:`sample_nb` / :func:`sample_np`: one
  time sample: load balance, spring forces, friction forces of both families, validity
  check, sums;
* :func:`interp_periodic_nb`: bilinear periodic interpolation of sampled surfaces.

Mode codes of the sample kernels: ``MODE_FULL`` (full-contact limit, every spring carries
the same force), ``MODE_LOAD`` (mean force per spring held, ``c`` solved) and
``MODE_SEPARATION`` (``c`` held).
"""

from __future__ import annotations

import math

import numpy as np

from frictionlab._jit import numba

MODE_FULL = 0
MODE_LOAD = 1
MODE_SEPARATION = 2

#: Index of each quantity in the tuple returned by the sample kernels.
SAMPLE_FIELDS = (
    "c",  # offset l0 - d (m)
    "iterations",  # load-solve iterations
    "force_compressed",  # sum of compressive spring forces over the stations (N)
    "x",  # sum of F_c * (H1x + H2x) (N)
    "y",  # sum of F_c * (H1y + H2y) (N)
    "force_total",  # sum of all spring forces, tensile included (N)
    "n_compressed",
    "n_tensile",
    "n_invalid",  # compressed contacts (of both families) violating Eq 1
    "first_invalid",  # station index of the first invalid contact, -1 if none
    "invalid_family",  # 1: upper-fixed spring on surface 1, 2: lower-fixed on surface 2
)

_MAX_NEWTON = 100

#: Floating-point licences for the reductions (reassociation lets them vectorise; no
#: assumption about NaN or infinity is made).
_FAST = {"reassoc", "contract", "nsz"}


@numba.njit(cache=True, inline="always")
def _h_one(mu0: float, gx: float, gy: float, cb: float, sb: float) -> tuple[float, float, float]:
    """H = (-F_x, -F_y) per unit F_z and the denominator n_z - mu0 t_z (frame-free Eqs 1-4)."""
    inv_n = 1.0 / math.sqrt(1.0 + gx * gx + gy * gy)
    a = gx * cb + gy * sb
    inv_t = 1.0 / math.sqrt(1.0 + a * a)
    den = inv_n - mu0 * a * inv_t
    big_n = 1.0 / den
    hx = big_n * (gx * inv_n + mu0 * cb * inv_t)
    hy = big_n * (gy * inv_n + mu0 * sb * inv_t)
    return hx, hy, den


@numba.njit(cache=True, nogil=True)
def multipliers_nb(
    mu0: float, gx: np.ndarray, gy: np.ndarray, cb: float, sb: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Multipliers (hx, hy) and denominators of many gradients (1-D arrays).

    Where the denominator is not positive (a contact violating Eq 1) the multipliers are
    set to 0: the caller reports such contacts from ``den`` and never uses their value.
    """
    n = gx.size
    hx = np.empty(n)
    hy = np.empty(n)
    den = np.empty(n)
    for i in range(n):
        a, b, d = _h_one(mu0, gx[i], gy[i], cb, sb)
        if not d > 0.0:  # invalid contact (Eq 1): flagged by den, multipliers unused
            a = 0.0
            b = 0.0
        hx[i], hy[i], den[i] = a, b, d
    return hx, hy, den


def multipliers_np(
    mu0: float, gx: np.ndarray, gy: np.ndarray, cb: float, sb: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """NumPy twin of :func:`multipliers_nb`."""
    inv_n = 1.0 / np.sqrt(1.0 + gx * gx + gy * gy)
    a = gx * cb + gy * sb
    inv_t = 1.0 / np.sqrt(1.0 + a * a)
    den = inv_n - mu0 * a * inv_t
    with np.errstate(divide="ignore", invalid="ignore"):
        big_n = np.where(den > 0.0, 1.0 / den, 0.0)
        hx = big_n * (gx * inv_n + mu0 * cb * inv_t)
        hy = big_n * (gy * inv_n + mu0 * sb * inv_t)
    return hx, hy, den


@numba.njit(cache=True, fastmath=_FAST)
def _gap_stats(gap: np.ndarray) -> tuple[float, float, float]:
    """(max, min, sum) of the gaps."""
    gmax = gap[0]
    gmin = gap[0]
    gsum = 0.0
    for i in range(gap.size):
        gmax = max(gmax, gap[i])
        gmin = min(gmin, gap[i])
        gsum += gap[i]
    return gmax, gmin, gsum


@numba.njit(cache=True, nogil=True)
def _mean_force(
    gap: np.ndarray, bounds: np.ndarray, cols: int, c: float, kc: float, kt: float
) -> tuple[float, float, int]:
    """Mean spring force per station at offset c, its slope in c, and the compressed count.

    Summed per chunk of rows of ``cols`` stations (``bounds``, see :func:`chunk_bounds`),
    the chunks in order.
    """
    f = 0.0
    counted = 0.0
    for k in range(bounds.size - 1):
        part, part_count = _force_sum(gap[bounds[k] * cols : bounds[k + 1] * cols], c, kc, kt)
        f += part
        counted += part_count
    n = gap.size
    count = int(counted)
    return f / n, (kc * count + kt * (n - count)) / n, count


@numba.njit(cache=True)
def solve_offset_nb(
    gap: np.ndarray, kc: float, kt: float, load: float, c_start: float
) -> tuple[float, int]:
    """Offset c with mean(k_c max(c-g,0) + k_t min(c-g,0)) = load (1-D ``gap``, m).

    See :func:`_solve_offset`; this entry point sums the stations serially in one chunk.
    """
    gmax, gmin, gsum = _gap_stats(gap)
    bounds = np.array([0, 1], dtype=np.int64)
    return _solve_offset(
        gap, bounds, gap.size, kc, kt, load, c_start, gmax, gmin, gsum, 0.0, 0.0, False
    )  # fmt: skip


@numba.njit(cache=True, nogil=True)
def _solve_offset(
    gap: np.ndarray,
    bounds: np.ndarray,
    cols: int,
    kc: float,
    kt: float,
    load: float,
    c_start: float,
    gmax: float,
    gmin: float,
    gsum: float,
    f_start: float,
    count_start: float,
    have_start: bool,
) -> tuple[float, int]:
    """Offset c with mean(k_c max(c-g,0) + k_t min(c-g,0)) = load: the load balance.

    The mean force is piecewise linear, increasing and convex in c (``0 <= k_t <= k_c``).
    A Newton step solves the linear piece of its starting point exactly; when the step
    lands on the same piece (same compressed count) the root is found. From the right the
    iterates decrease monotonically; a step from the left overshoots to the right; a
    start with zero slope (no spring compressed, ``k_t = 0``) jumps to the one-spring
    solution ``min(gap) + n load/k_c``, which is right of the root. Bisection is the
    fallback. ``gmax, gmin, gsum``: statistics of the gaps; with ``have_start`` the force
    sum and compressed count at a finite ``c_start`` are already known (computed with
    the gaps). Returns (c, iterations).
    """
    n = gap.size
    c_full = gsum / n + load / kc  # every spring compressed
    if c_full >= gmax:
        return c_full, 0
    c = c_start if math.isfinite(c_start) else c_full
    if have_start and math.isfinite(c_start):
        count = int(count_start)
        f, fp = f_start / n, (kc * count + kt * (n - count)) / n
    else:
        f, fp, count = _mean_force(gap, bounds, cols, c, kc, kt)
    for it in range(1, _MAX_NEWTON + 1):
        if fp <= 0.0:
            # No spring compressed (k_t = 0): the root lies above min(gap); the
            # one-spring solution is at or right of it (convexity).
            c = gmin + n * load / kc
            f, fp, count = _mean_force(gap, bounds, cols, c, kc, kt)
            if fp <= 0.0:  # the load is below the rounding of the gaps
                return c, it
            continue
        c_new = c - (f - load) / fp
        f, fp, count_new = _mean_force(gap, bounds, cols, c_new, kc, kt)
        c = c_new
        if count_new == count:
            return c, it
        count = count_new
    # Fallback: bisection on a bracket of the root.
    span = abs(load) / kc + (gmax - gmin) + 1.0e-300
    lo = gmin - (abs(load) / kt if kt > 0.0 else 0.0) - span
    hi = gmax + span
    steps = 0
    while steps < 200 and hi - lo > 4e-16 * (abs(lo) + abs(hi)):
        steps += 1
        mid = 0.5 * (lo + hi)
        f, _, _ = _mean_force(gap, bounds, cols, mid, kc, kt)
        if f < load:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi), _MAX_NEWTON + steps


def solve_offset_np(gap: np.ndarray, kc: float, kt: float, load: float) -> tuple[float, int]:
    """Exact load balance by sorting (independent of the Newton solver of the numba engine).

    Between consecutive sorted gaps the mean force is linear in c; prefix sums give it at
    every breakpoint, and the root is found by interpolation in the bracketing segment.
    """
    g = np.sort(gap)
    n = g.size
    c_full = g.mean() + load / kc
    if c_full >= g[-1]:
        return float(c_full), 0
    prefix = np.concatenate(([0.0], np.cumsum(g)))
    m = np.arange(n + 1)  # springs with gap < c for c in (g[m-1], g[m]]
    total = prefix[-1]

    def mean_force(c: np.ndarray, k: np.ndarray) -> np.ndarray:
        compressed = kc * (k * c - prefix[k])
        tensile = kt * ((n - k) * c - (total - prefix[k]))
        return np.asarray((compressed + tensile) / n)

    # Force at each breakpoint c = g[j] (springs 0..j-1 compressed, j..n-1 not).
    f_break = mean_force(g, m[:-1])
    j = int(np.searchsorted(f_break, load, side="right"))  # root in (g[j-1], g[j]]
    if j == n:
        return float(c_full), 0
    if j == 0:
        if kt <= 0.0:
            raise ValueError("a non-positive load cannot be carried with k_t = 0")
        # All springs tensile: kt * (c - mean g) = load.
        return float(g.mean() + load / kt), 1
    k = j  # springs 0..j-1 compressed
    slope = (kc * k + kt * (n - k)) / n
    c0 = float(g[j - 1])
    return float(c0 + (load - float(mean_force(np.array([c0]), np.array([k]))[0])) / slope), 1


@numba.njit(cache=True)
def _detach_force(
    g: np.ndarray, prefix: np.ndarray, c: float, m1: int, m2: int, kc: float, kt: float
) -> tuple[float, float]:
    """Mean force at c and its slope, springs [0, m1) compressed and [m1, m2) attached."""
    n = g.size
    compressed = kc * (m1 * c - prefix[m1])
    stretched = kt * ((m2 - m1) * c - (prefix[m2] - prefix[m1]))
    return (compressed + stretched) / n, (kc * m1 + kt * (m2 - m1)) / n


@numba.njit(cache=True)
def solve_offset_detach_nb(
    gap: np.ndarray, kc: float, kt: float, load: float, detach: float
) -> tuple[float, int]:
    """Load balance with detaching springs: the **largest** c with mean force == load.

    Spring law: ``k_c u`` for u > 0, ``k_t u`` for ``-detach <= u <= 0``, 0 below (a spring
    stretched beyond ``detach`` has let go). The mean force is piecewise linear and
    increasing between breakpoints (``c = g`` and ``c = g - detach``) but drops where a
    spring re-attaches, so it can equal the load several times. The root taken is the
    largest one, ``sup{c : f(c) <= load}``: the state reached by pulling the surfaces apart
    from full contact, springs letting go one by one. Gaps sorted once; prefix sums give
    the force on every interval; the intervals are scanned from the top. Returns
    ``(c, 1)``, or ``(nan, 1)`` when the load is below the largest adhesive force (the
    surfaces pull off).
    """
    g = np.sort(gap)
    n = g.size
    prefix = np.zeros(n + 1)
    for i in range(n):
        prefix[i + 1] = prefix[i] + g[i]
    c_full = prefix[n] / n + load / kc
    if c_full >= g[n - 1]:
        return c_full, 0
    breaks = np.sort(np.concatenate((g, g - detach)))
    for k in range(breaks.size - 2, -1, -1):
        lo = breaks[k]
        hi = breaks[k + 1]
        if not hi > lo:
            continue
        mid = 0.5 * (lo + hi)
        m1 = np.searchsorted(g, mid)  # g < c: compressed
        m2 = np.searchsorted(g, mid + detach, side="right")  # g <= c + detach: attached
        f_lo, slope = _detach_force(g, prefix, lo, m1, m2, kc, kt)
        if f_lo <= load:
            if slope > 0.0:
                return min(lo + (load - f_lo) / slope, hi), 1
            return hi, 1
    if load >= 0.0:  # every spring detached carries exactly zero load
        return breaks[0], 1
    return math.nan, 1


def solve_offset_detach_np(
    gap: np.ndarray, kc: float, kt: float, load: float, detach: float
) -> tuple[float, int]:
    """NumPy twin of :func:`solve_offset_detach_nb` (all intervals evaluated at once)."""
    g = np.sort(gap)
    n = g.size
    prefix = np.concatenate(([0.0], np.cumsum(g)))
    c_full = g.mean() + load / kc
    if c_full >= g[-1]:
        return float(c_full), 0
    breaks = np.sort(np.concatenate((g, g - detach)))
    lo, hi = breaks[:-1], breaks[1:]
    mid = 0.5 * (lo + hi)
    m1 = np.searchsorted(g, mid)
    m2 = np.searchsorted(g, mid + detach, side="right")
    f_lo = (kc * (m1 * lo - prefix[m1]) + kt * ((m2 - m1) * lo - (prefix[m2] - prefix[m1]))) / n
    slope = (kc * m1 + kt * (m2 - m1)) / n
    ok = np.flatnonzero((hi > lo) & (f_lo <= load))
    if ok.size == 0:
        return (float(breaks[0]), 1) if load >= 0.0 else (math.nan, 1)
    k = int(ok[-1])
    if slope[k] > 0.0:
        return float(min(lo[k] + (load - f_lo[k]) / slope[k], hi[k])), 1
    return float(hi[k]), 1


@numba.njit(cache=True, fastmath=_FAST)
def _difference(
    gap: np.ndarray, z2: np.ndarray, z1: np.ndarray, p0: int, q0: int, length: int
) -> None:
    """gap[p0 + m] = z2[q0 + m] - z1[p0 + m] for m < length (one contiguous run)."""
    for m in range(length):
        gap[p0 + m] = z2[q0 + m] - z1[p0 + m]


@numba.njit(cache=True, fastmath=_FAST)
def _accumulate_row(
    gap: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    den1: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    den2: np.ndarray,
    p0: int,
    q0: int,
    length: int,
    c: float,
    kc: float,
    kt: float,
    full: bool,
    detach: float,
    drop: bool,
) -> tuple[float, float, float, float, int, int, int]:
    """Sums over stations p0 .. p0+length-1 reading surface 2 at q0 .. q0+length-1."""
    fsum = 0.0
    xsum = 0.0
    ysum = 0.0
    ftot = 0.0
    n_comp = 0
    n_tens = 0
    n_inv = 0
    for m in range(length):
        p = p0 + m
        q = q0 + m
        if full:
            fc = 1.0
            ft = 0.0
        else:
            u = c - gap[p]
            fc = kc * max(u, 0.0)
            ft = kt * min(u, 0.0) if u >= -detach else 0.0
        bad = (den1[p] <= 0.0) + (den2[q] <= 0.0)
        ftot += fc + ft
        # drop: an invalid contact carries no load in the average (its H is already 0)
        fsum += fc * (1.0 - 0.5 * bad) if drop else fc
        xsum += fc * (h1x[p] + h2x[q])
        ysum += fc * (h1y[p] + h2y[q])
        n_comp += fc > 0.0
        n_tens += ft < 0.0
        n_inv += bad if fc > 0.0 else 0
    return fsum, xsum, ysum, ftot, n_comp, n_tens, n_inv


@numba.njit(cache=True, fastmath=_FAST)
def _accumulate_lean(
    gap: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    p0: int,
    q0: int,
    length: int,
    c: float,
    kc: float,
    kt: float,
    full: bool,
    detach: float,
) -> tuple[float, float, float, float, float, float]:
    """:func:`_accumulate_row` when no contact can violate Eq 1: no denominators read.

    Counts are accumulated as floats (exact below 2^53) so that the loop vectorises.
    """
    fsum = 0.0
    xsum = 0.0
    ysum = 0.0
    ftot = 0.0
    n_comp = 0.0
    n_tens = 0.0
    for m in range(length):
        p = p0 + m
        q = q0 + m
        u = c - gap[p]
        fc = 1.0 if full else kc * max(u, 0.0)
        ft = 0.0 if full or u < -detach else kt * min(u, 0.0)
        ftot += fc + ft
        fsum += fc
        xsum += fc * (h1x[p] + h2x[q])
        ysum += fc * (h1y[p] + h2y[q])
        n_comp += 1.0 if fc > 0.0 else 0.0
        n_tens += 1.0 if ft < 0.0 else 0.0
    return fsum, xsum, ysum, ftot, n_comp, n_tens


#: Stations per chunk of the sample kernels (whole rows of the station grid, at least one):
#: the chunks are the unit of work of the threads and of the partial sums, fixed by the
#: grid alone, so the results do not depend on the number of threads.
CHUNK_STATIONS = 1 << 14

#: Columns of the per-chunk partial results.
PART_COLUMNS = 8


@numba.njit(cache=True)
def chunk_bounds(nx: int, ny: int) -> np.ndarray:
    """First row of every chunk and the row count at the end (int64, 1-D).

    Rows are the grid rows in 2-D (nx rows of ny stations) and one row of nx stations in
    1-D (ny = 1).
    """
    rows, cols = (1, nx) if ny == 1 else (nx, ny)
    step = max(1, CHUNK_STATIONS // cols)
    m = (rows + step - 1) // step
    bounds = np.empty(m + 1, dtype=np.int64)
    for i in range(m):
        bounds[i] = i * step
    bounds[m] = rows
    return bounds


def workspace(nx: int, ny: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Buffers of :func:`sample_into_nb` for an nx x ny grid: (gaps, chunk bounds, partials)."""
    bounds = chunk_bounds(nx, ny)
    return np.empty(nx * ny), bounds, np.empty((bounds.size - 1, PART_COLUMNS))


@numba.njit(cache=True, fastmath=_FAST)
def _force_sum(gap: np.ndarray, c: float, kc: float, kt: float) -> tuple[float, float]:
    """Sum of the spring forces at offset c and the compressed count (as a float)."""
    f = 0.0
    count = 0.0
    for i in range(gap.size):
        u = c - gap[i]
        f += kc * max(u, 0.0) + kt * min(u, 0.0)
        count += 1.0 if u > 0.0 else 0.0
    return f, count


@numba.njit(cache=True, fastmath=_FAST)
def _gap_chunk(
    gap: np.ndarray,
    z1: np.ndarray,
    z2: np.ndarray,
    r0: int,
    r1: int,
    rows: int,
    cols: int,
    rshift: int,
    cshift: int,
    c: float,
    kc: float,
    kt: float,
    part: np.ndarray,
) -> None:
    """Gaps of rows r0 .. r1-1; in ``part``: their (max, min, sum) and, for a finite c,
    the force sum and compressed count at c (taken while the chunk is in cache)."""
    for i in range(r0, r1):
        ii = i - rshift
        if ii < 0:
            ii += rows
        _difference(gap, z2, z1, i * cols, ii * cols + cols - cshift, cshift)
        _difference(gap, z2, z1, i * cols + cshift, ii * cols, cols - cshift)
    chunk = gap[r0 * cols : r1 * cols]
    part[0], part[1], part[2] = _gap_stats(chunk)
    if math.isfinite(c):
        part[3], part[4] = _force_sum(chunk, c, kc, kt)


@numba.njit(cache=True)
def _sums_chunk(
    gap: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    den1: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    den2: np.ndarray,
    r0: int,
    r1: int,
    rows: int,
    cols: int,
    rshift: int,
    cshift: int,
    c: float,
    kc: float,
    kt: float,
    full: bool,
    detach: float,
    drop: bool,
    check: bool,
    part: np.ndarray,
) -> None:
    """The sums of ``SAMPLE_FIELDS`` (force, x, y, total, counts) over rows r0 .. r1-1."""
    part[:] = 0.0
    for i in range(r0, r1):
        ii = i - rshift
        if ii < 0:
            ii += rows
        # k in [0, cshift): kk = k - cshift + cols ; k in [cshift, cols): kk = k - cshift
        for k0, q0, length in (
            (0, ii * cols + cols - cshift, cshift),
            (cshift, ii * cols, cols - cshift),
        ):
            if length == 0:
                continue
            if check:
                fsum, xsum, ysum, ftot, n_comp, n_tens, n_inv = _accumulate_row(
                    gap, h1x, h1y, den1, h2x, h2y, den2, i * cols + k0, q0, length, c, kc,
                    kt, full, detach, drop,
                )  # fmt: skip
                part[6] += n_inv
            else:
                fsum, xsum, ysum, ftot, comp, tens = _accumulate_lean(
                    gap, h1x, h1y, h2x, h2y, i * cols + k0, q0, length, c, kc, kt, full, detach
                )
                n_comp, n_tens = int(comp), int(tens)
            part[0] += fsum
            part[1] += xsum
            part[2] += ysum
            part[3] += ftot
            part[4] += n_comp
            part[5] += n_tens


@numba.njit(cache=True, nogil=True)
def sample_nb(
    z1: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    den1: np.ndarray,
    z2: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    den2: np.ndarray,
    nx: int,
    ny: int,
    kx: int,
    ky: int,
    kc: float,
    kt: float,
    mode: int,
    load: float,
    c_in: float,
    detach: float = math.inf,
    drop: bool = False,
) -> tuple[float, int, float, float, float, float, int, int, int, int, int]:
    """One time sample over all stations (serial, fresh buffers); see :func:`sample_into_nb`."""
    gap = np.empty(nx * ny)
    bounds = chunk_bounds(nx, ny)
    parts = np.empty((bounds.size - 1, PART_COLUMNS))
    return sample_into_nb(
        z1, h1x, h1y, den1, z2, h2x, h2y, den2, nx, ny, kx, ky, kc, kt, mode, load, c_in,
        detach, drop, True, gap, bounds, parts,
    )  # fmt: skip


@numba.njit(cache=True, nogil=True)
def sample_into_nb(
    z1: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    den1: np.ndarray,
    z2: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    den2: np.ndarray,
    nx: int,
    ny: int,
    kx: int,
    ky: int,
    kc: float,
    kt: float,
    mode: int,
    load: float,
    c_in: float,
    detach: float,
    drop: bool,
    check: bool,
    gap: np.ndarray,
    bounds: np.ndarray,
    parts: np.ndarray,
) -> tuple[float, int, float, float, float, float, int, int, int, int, int]:
    """One time sample (the load balance and the sums) over all stations; see ``SAMPLE_FIELDS``.

    Stations are the nx x ny grid, flattened row-major (1-D: ny = 1). ``z1, h1x, h1y,
    den1``: surface 1 at the stations with its multipliers and Eq 1 denominators
    (upper-fixed springs). ``z2, h2x, h2y, den2``: the same for surface 2 on the station
    grid, read at the station index shifted by whole stations (kx, ky), 0 <= kx < nx,
    0 <= ky < ny: station (i, k) sees entry ((i - kx) mod nx, (k - ky) mod ny). Both
    families share the station and its compression ``u = c - gap``; only compressed
    springs carry friction (Eqs 5-9 summed per station); with ``drop`` a contact
    violating Eq 1 is left out of the compressed-force sum too.

    ``check = False`` promises that no denominator is <= 0 (the caller checked once): the
    denominators are then not read. ``gap`` (n), ``bounds`` and ``parts``: work buffers
    from :func:`workspace`, overwritten (nothing is allocated). The stations are worked on
    in chunks of whole rows (:func:`chunk_bounds`) whose partial sums are added in chunk
    order; within a chunk each row is two contiguous runs, before and after the wrap of
    the shifted index, which the compiler vectorises. The pass that forms a chunk's gaps
    also takes their statistics and, with a finite ``c_in`` under load control, the first
    force sum of the load balance while the chunk is in cache. The kernel releases the
    GIL: samples of one lattice can run on several threads, each with its own buffers.
    """
    rows, cols, rshift, cshift = (1, nx, 0, kx) if ny == 1 else (nx, ny, kx, ky)
    nch = bounds.size - 1
    newton = mode == MODE_LOAD and not (detach < math.inf and kt > 0.0)
    c_first = c_in if newton else math.nan
    full = mode == MODE_FULL
    for k in range(nch):
        _gap_chunk(
            gap, z1, z2, bounds[k], bounds[k + 1], rows, cols, rshift, cshift, c_first, kc, kt,
            parts[k],
        )  # fmt: skip
    iterations = 0
    c = c_in
    if mode == MODE_LOAD:
        if newton:
            gmax = parts[0, 0]
            gmin = parts[0, 1]
            gsum = 0.0
            f_start = 0.0
            count_start = 0.0
            for k in range(nch):
                gmax = max(gmax, parts[k, 0])
                gmin = min(gmin, parts[k, 1])
                gsum += parts[k, 2]
                f_start += parts[k, 3]
                count_start += parts[k, 4]
            c, iterations = _solve_offset(
                gap, bounds, cols, kc, kt, load, c_in, gmax, gmin, gsum,
                f_start, count_start, True,
            )  # fmt: skip
        else:
            c, iterations = solve_offset_detach_nb(gap, kc, kt, load, detach)
    for k in range(nch):
        _sums_chunk(
            gap, h1x, h1y, den1, h2x, h2y, den2, bounds[k], bounds[k + 1], rows, cols, rshift,
            cshift, c, kc, kt, full, detach, drop, check, parts[k],
        )  # fmt: skip
    fsum = 0.0
    xsum = 0.0
    ysum = 0.0
    ftot = 0.0
    comp = 0.0
    tens = 0.0
    inv = 0.0
    for k in range(nch):
        fsum += parts[k, 0]
        xsum += parts[k, 1]
        ysum += parts[k, 2]
        ftot += parts[k, 3]
        comp += parts[k, 4]
        tens += parts[k, 5]
        inv += parts[k, 6]
    n_comp = int(comp)
    n_tens = int(tens)
    n_inv = int(inv)
    first = -1
    family = 0
    if n_inv > 0:  # locate the first invalid contact (rare: the computation stops)
        for i in range(nx):
            ii = i - kx
            if ii < 0:
                ii += nx
            for k in range(ny):
                kk = k - ky
                if kk < 0:
                    kk += ny
                p = i * ny + k
                compressed = full or c - gap[p] > 0.0
                if compressed and (den1[p] <= 0.0 or den2[ii * ny + kk] <= 0.0):
                    first = p
                    family = 1 if den1[p] <= 0.0 else 2
                    break
            if first >= 0:
                break
    return c, iterations, fsum, xsum, ysum, ftot, n_comp, n_tens, n_inv, first, family


def sample_np(
    z1: np.ndarray,
    h1x: np.ndarray,
    h1y: np.ndarray,
    den1: np.ndarray,
    z2: np.ndarray,
    h2x: np.ndarray,
    h2y: np.ndarray,
    den2: np.ndarray,
    nx: int,
    ny: int,
    kx: int,
    ky: int,
    kc: float,
    kt: float,
    mode: int,
    load: float,
    c_in: float,
    detach: float = math.inf,
    drop: bool = False,
) -> tuple[float, int, float, float, float, float, int, int, int, int, int]:
    """NumPy twin of :func:`sample_nb` (load balance by sorting instead of Newton)."""

    def shifted(a: np.ndarray) -> np.ndarray:
        return np.roll(a.reshape(nx, ny), (kx, ky), axis=(0, 1)).ravel()

    gap = shifted(z2) - z1
    iterations = 0
    c = c_in
    if mode == MODE_LOAD:
        if detach < math.inf and kt > 0.0:
            c, iterations = solve_offset_detach_np(gap, kc, kt, load, detach)
        else:
            c, iterations = solve_offset_np(gap, kc, kt, load)
    if mode == MODE_FULL:
        fc = np.ones(gap.size)
        ft = np.zeros(gap.size)
    else:
        u = c - gap
        fc = np.where(u > 0.0, kc * u, 0.0)
        ft = np.where((u > 0.0) | (u < -detach), 0.0, kt * u)
    comp = fc > 0.0
    bad1 = den1[comp] <= 0.0
    bad2 = shifted(den2)[comp] <= 0.0
    bad = bad1 | bad2
    idx = np.flatnonzero(comp)
    first = int(idx[bad][0]) if bad.any() else -1
    family = 0 if first < 0 else (1 if bool(bad1[bad][0]) else 2)
    f = fc[comp]
    f_kept = f * (1.0 - 0.5 * (bad1.astype(float) + bad2)) if drop else f
    with np.errstate(invalid="ignore", over="ignore"):
        x = float(np.sum(f * (h1x[comp] + shifted(h2x)[comp])))
        y = float(np.sum(f * (h1y[comp] + shifted(h2y)[comp])))
    return (
        float(c),
        iterations,
        float(f_kept.sum()),
        x,
        y,
        float(fc.sum() + ft.sum()),
        int(comp.sum()),
        int(np.count_nonzero(ft < 0.0)),
        int(bad1.sum() + bad2.sum()),
        first,
        family,
    )


@numba.njit(cache=True, inline="always")
def _cell(q: float, d: float, n: int) -> tuple[int, int, float]:
    """The periodic cell of coordinate ``q`` on ``n`` pixel centres ``(i + 1/2) d``.

    Returns the indices of the samples below and above ``q`` and the weight of the
    upper one (0 on a sample).
    """
    u = q / d - 0.5
    f = math.floor(u)
    i = int(f) % n
    return i, (i + 1) % n, u - f


@numba.njit(cache=True, inline="always")
def _bilinear(
    fields: np.ndarray, m: int, i0: int, i1: int, j0: int, j1: int, tx: float, ty: float
) -> float:
    """Field ``m`` interpolated between samples (i0, i1) x (j0, j1) with weights tx, ty."""
    return (1.0 - tx) * ((1.0 - ty) * fields[m, i0, j0] + ty * fields[m, i0, j1]) + (
        tx * ((1.0 - ty) * fields[m, i1, j0] + ty * fields[m, i1, j1])
    )


@numba.njit(cache=True, nogil=True)
def interp_periodic_nb(
    fields: np.ndarray,
    dx: float,
    dy: float,
    xq: np.ndarray,
    yq: np.ndarray,
) -> np.ndarray:
    """Bilinear periodic interpolation of ``fields`` (k, nx, ny) on the outer grid xq x yq.

    Samples sit at pixel centres ``((i + 1/2) dx, (j + 1/2) dy)``; a query on a sample
    returns it exactly. ``xq`` (m) and ``yq`` (m) are 1-D; the result is (k, xq.size,
    yq.size). For a line scan pass ny = 1 and any ``yq`` of length 1.
    """
    k, nx, ny = fields.shape
    out = np.empty((k, xq.size, yq.size))
    ix0 = np.empty(xq.size, dtype=np.int64)
    ix1 = np.empty(xq.size, dtype=np.int64)
    wx = np.empty(xq.size)
    for a in range(xq.size):
        ix0[a], ix1[a], wx[a] = _cell(xq[a], dx, nx)
    iy0 = np.zeros(yq.size, dtype=np.int64)
    iy1 = np.zeros(yq.size, dtype=np.int64)
    wy = np.zeros(yq.size)
    if ny > 1:
        for b in range(yq.size):
            iy0[b], iy1[b], wy[b] = _cell(yq[b], dy, ny)
    for m in range(k):
        for a in range(xq.size):
            i0, i1, tx = ix0[a], ix1[a], wx[a]
            for b in range(yq.size):
                out[m, a, b] = _bilinear(fields, m, i0, i1, iy0[b], iy1[b], tx, wy[b])
    return out


@numba.njit(cache=True, nogil=True)
def interp_points_nb(
    fields: np.ndarray, dx: float, dy: float, xq: np.ndarray, yq: np.ndarray
) -> np.ndarray:
    """Bilinear periodic interpolation of ``fields`` (k, nx, ny) at the points (xq, yq).

    Same convention as :func:`interp_periodic_nb`; ``xq`` and ``yq`` are 1-D arrays of
    equal length; the result is (k, xq.size).
    """
    k, nx, ny = fields.shape
    out = np.empty((k, xq.size))
    for p in range(xq.size):
        i0, i1, tx = _cell(xq[p], dx, nx)
        j0, j1, ty = _cell(yq[p], dy, ny)
        for m in range(k):
            out[m, p] = _bilinear(fields, m, i0, i1, j0, j1, tx, ty)
    return out
