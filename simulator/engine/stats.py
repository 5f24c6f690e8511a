"""Running per-sensor statistics in float64, merged exactly.

Each kernel thread returns, for its block of samples, a shift K (its first
sample) and the shifted sums Σ(x − K), Σ(x − K)². Blocks are merged with the
pairwise update of Chan, Golub and LeVeque, which adds δ² terms only where
block means differ, so a constant estimator keeps a variance of exactly 0.

References
----------
T. F. Chan, G. H. Golub, R. J. LeVeque, "Algorithms for computing the sample
variance: analysis and recommendations", The American Statistician 37(3), 1983.
"""

from __future__ import annotations

import numpy as np

__all__ = ["RunningStats", "GroupStats", "GroupBatchStats", "Z95", "lit_variance", "z_for_confidence"]

#: two-sided 95% normal quantile, for confidence half-widths
Z95 = 1.959963984540054


def z_for_confidence(confidence: float) -> float:
    """Two-sided normal quantile: the half-width of a ``confidence`` interval
    in standard errors (0.95 → 1.96, 0.999 → 3.29)."""
    from statistics import NormalDist

    return NormalDist().inv_cdf(0.5 + 0.5 * confidence)


class RunningStats:
    """Count, mean and sum of squared deviations (M2) per sensor and channel.

    Parameters
    ----------
    n_sensors : int
    n_channels : int
        2: radiometric and photometric.
    """

    def __init__(self, n_sensors: int, n_channels: int = 2):
        self.count = np.zeros(n_sensors, np.int64)
        self.mean = np.zeros((n_sensors, n_channels))
        self.m2 = np.zeros((n_sensors, n_channels))

    def merge(self, sensor: np.ndarray, count: np.ndarray, mean: np.ndarray, m2: np.ndarray) -> None:
        """Merge one block per sensor (``sensor`` has no repeats) into the totals."""
        na = self.count[sensor].astype(np.float64)[:, None]
        nb = count.astype(np.float64)[:, None]
        n = na + nb
        delta = mean - self.mean[sensor]
        first = na == 0  # nothing yet: take the block as it is
        self.mean[sensor] = np.where(first, mean, self.mean[sensor] + delta * (nb / n))
        self.m2[sensor] = np.where(first, m2, self.m2[sensor] + m2 + delta * delta * (na * nb / n))
        self.count[sensor] += count

    @staticmethod
    def reduce_blocks(
        block_sensor: np.ndarray,
        block_count: np.ndarray,
        shift: np.ndarray,
        s1: np.ndarray,
        s2: np.ndarray,
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Collapse kernel-thread blocks into one block per sensor.

        Parameters
        ----------
        block_sensor : ndarray, shape (B,)
            Sensor of each thread block; blocks of one sensor are contiguous.
        block_count : ndarray, shape (B,)
        shift, s1, s2 : ndarray, shape (B, C)
            K, Σ(x − K) and Σ(x − K)² per block.

        Returns
        -------
        sensors, counts, means, m2s
        """
        cnt = block_count.astype(np.float64)[:, None]
        bmean = shift + s1 / cnt
        bm2 = np.maximum(s2 - s1 * s1 / cnt, 0.0)
        starts = np.flatnonzero(np.r_[True, block_sensor[1:] != block_sensor[:-1]])
        sensors = block_sensor[starts]
        counts = np.add.reduceat(block_count, starts)
        # mean relative to the first block's mean: exact when all block means agree
        ref = np.repeat(bmean[starts], np.diff(np.r_[starts, len(block_sensor)]), axis=0)
        dev = bmean - ref
        means = bmean[starts] + np.add.reduceat(dev * cnt, starts) / counts[:, None]
        spread = bmean - np.repeat(means, np.diff(np.r_[starts, len(block_sensor)]), axis=0)
        m2s = np.add.reduceat(bm2 + cnt * spread * spread, starts)
        return sensors, counts, means, m2s

    def stderr(self) -> np.ndarray:
        """Standard error of each mean, shape (S, C): √(M2 / (n(n − 1)))."""
        n = self.count.astype(np.float64)[:, None]
        with np.errstate(invalid="ignore", divide="ignore"):
            se = np.sqrt(self.m2 / (n * (n - 1.0)))
        return np.where(n > 1, se, np.inf)


class GroupStats:
    """Count, mean vector and co-moment matrix per sensor and channel: the light groups' joint statistics.

    Each sample of a sensor is a vector x (G,) per channel, its light from
    each of G groups; the estimates of the group readings are the means
    x̄_g, and their covariance is ``M / (n (n − 1))`` with M the co-moment
    Σ(x − x̄)(x − x̄)ᵀ.

    Parameters
    ----------
    n_sensors : int
    n_groups : int
    n_channels : int
        2: radiometric and photometric.

    Attributes
    ----------
    count : ndarray, shape (S,)
    mean : ndarray, shape (S, C, G)
    comoment : ndarray, shape (S, C, G, G)

    Notes
    -----
    Blocks merge by the multivariate form of the pairwise update (Chan,
    Golub, LeVeque 1983): for blocks a, b with n = n_a + n_b and
    δ = x̄_b − x̄_a,

        M = M_a + M_b + δ δᵀ · n_a n_b / n,

    so a group with a constant estimator keeps exactly zero variance and zero
    covariance with every other group.
    """

    def __init__(self, n_sensors: int, n_groups: int, n_channels: int = 2):
        self.count = np.zeros(n_sensors, np.int64)
        self.mean = np.zeros((n_sensors, n_channels, n_groups))
        self.comoment = np.zeros((n_sensors, n_channels, n_groups, n_groups))

    def merge(self, sensor: np.ndarray, count: np.ndarray, mean: np.ndarray, comoment: np.ndarray) -> None:
        """Merge one block per sensor (``sensor`` has no repeats); ``mean`` (B, C, G), ``comoment`` (B, C, G, G)."""
        na = self.count[sensor].astype(np.float64)[:, None, None]
        nb = count.astype(np.float64)[:, None, None]
        n = na + nb
        delta = mean - self.mean[sensor]
        first = (na == 0)[..., None]
        self.mean[sensor] = np.where(first[..., 0], mean, self.mean[sensor] + delta * (nb / n))
        outer = delta[..., :, None] * delta[..., None, :] * (na * nb / n)[..., None]
        self.comoment[sensor] = np.where(first, comoment, self.comoment[sensor] + comoment + outer)
        self.count[sensor] += count

    @staticmethod
    def reduce_blocks(block_sensor: np.ndarray, block_count: np.ndarray, shift: np.ndarray, s1: np.ndarray,
                      cross: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
        """Collapse kernel-thread blocks into one block per sensor.

        Parameters
        ----------
        block_sensor, block_count : ndarray, shape (B,)
            As for :meth:`RunningStats.reduce_blocks` (blocks of one sensor contiguous).
        shift, s1 : ndarray, shape (B, G, C)
            K_g and Σ(x_g − K_g) per block.
        cross : ndarray, shape (B, G, G, C)
            Σ(x_g − K_g)(x_h − K_h), filled for h ≤ g (the lower triangle).

        Returns
        -------
        sensors, counts : ndarray, shape (S',)
        means : ndarray, shape (S', C, G)
        comoments : ndarray, shape (S', C, G, G)
        """
        cnt = block_count.astype(np.float64)
        s1 = np.transpose(s1, (0, 2, 1))  # (B, C, G)
        low = np.transpose(cross, (0, 3, 1, 2))  # (B, C, G, G)
        diag = np.einsum("bcgg->bcg", low)
        p = low + np.transpose(low, (0, 1, 3, 2)) - np.einsum("bcg,gh->bcgh", diag, np.eye(low.shape[-1]))
        bmean = np.transpose(shift, (0, 2, 1)) + s1 / cnt[:, None, None]
        bm = p - s1[..., :, None] * s1[..., None, :] / cnt[:, None, None, None]
        starts = np.flatnonzero(np.r_[True, block_sensor[1:] != block_sensor[:-1]])
        reps = np.diff(np.r_[starts, len(block_sensor)])
        sensors = block_sensor[starts]
        counts = np.add.reduceat(block_count, starts)
        ref = np.repeat(bmean[starts], reps, axis=0)
        w = cnt[:, None, None]
        means = bmean[starts] + np.add.reduceat((bmean - ref) * w, starts) / counts[:, None, None]
        spread = bmean - np.repeat(means, reps, axis=0)
        outer = spread[..., :, None] * spread[..., None, :] * w[..., None]
        comoments = np.add.reduceat(bm + outer, starts)
        return sensors, counts, means, comoments

    def cov(self) -> np.ndarray:
        """Covariance of the group means, shape (S, C, G, G): M / (n (n − 1)); inf below 2 samples."""
        n = self.count.astype(np.float64)[:, None, None, None]
        with np.errstate(invalid="ignore", divide="ignore"):
            c = self.comoment / (n * (n - 1.0))
        return np.where(n > 1, c, np.inf)


class GroupBatchStats:
    """Light groups' means and covariance from batch means: for many groups (sky patches).

    Each kernel thread returns only the sums Σx_g of its block of samples
    (no cross products: a thread's state is 2G slots, not G(G + 3)); the
    blocks, B_s per sensor of n_b samples each, are the batches.

    Parameters
    ----------
    n_sensors, n_groups, n_channels : int

    Attributes
    ----------
    count : ndarray, shape (S,)
        Samples N.
    blocks : ndarray, shape (S,)
        Batches B.
    total : ndarray, shape (S, C, G)
        Σx over all samples.
    w2 : ndarray, shape (S, C, G, G)
        Σ_b n_b x̄_b x̄_bᵀ.

    Notes
    -----
    With block means x̄_b and the grand mean x̄ = Σ_b n_b x̄_b / N, the
    covariance of x̄ is estimated as

    .. math:: \\hat C = \\frac{\\sum_b n_b (\\bar x_b - \\bar x)(\\bar x_b - \\bar x)^\\top}{N (B - 1)}
              = \\frac{W_2 - N \\bar x \\bar x^\\top}{N (B - 1)},

    unbiased for blocks of equal size (the blocks are independent: each
    sample has its own random stream). For a recombination d, dᵀĈd is the
    batch-means variance of dᵀx̄ with B − 1 degrees of freedom (the exact
    per-sample co-moment, :class:`GroupStats`, has N − 1): its relative
    error is about 1/sqrt(2(B − 1)), 13% at 1024 samples in blocks of 32.
    The raw second moment W₂ loses no precision that matters here: a patch's
    block means vary by tens of percent or more (few samples reach any one patch).
    """

    def __init__(self, n_sensors: int, n_groups: int, n_channels: int = 2):
        self.count = np.zeros(n_sensors, np.int64)
        self.blocks = np.zeros(n_sensors, np.int64)
        self.total = np.zeros((n_sensors, n_channels, n_groups))
        self.w2 = np.zeros((n_sensors, n_channels, n_groups, n_groups))

    def merge_blocks(self, block_sensor: np.ndarray, block_count: np.ndarray, block_sum: np.ndarray) -> None:
        """Add one launch's blocks: ``block_sum`` (B, G, C) the blocks' Σx, blocks of one sensor contiguous,
        each sensor in one run of blocks."""
        cnt = block_count.astype(np.float64)
        ok = block_count > 0
        bsum = np.transpose(block_sum, (0, 2, 1))[ok]  # (B, C, G)
        bs, cnt = block_sensor[ok], cnt[ok]
        if not len(bs):
            return
        starts = np.flatnonzero(np.r_[True, bs[1:] != bs[:-1]])
        ends = np.r_[starts[1:], len(bs)]
        sens = bs[starts]
        self.count[sens] += np.add.reduceat(cnt, starts).astype(np.int64)
        self.blocks[sens] += ends - starts
        self.total[sens] += np.add.reduceat(bsum, starts)
        y = bsum / np.sqrt(cnt)[:, None, None]
        for s, a, b in zip(sens, starts, ends):
            ys = y[a:b]  # (m, C, G)
            nz = np.flatnonzero(np.any(ys != 0.0, axis=(0, 1)))  # the groups this sensor's blocks reached
            if not len(nz):
                continue
            yc = np.ascontiguousarray(np.transpose(ys[:, :, nz], (1, 0, 2)))  # (C, m, K)
            self.w2[s][np.ix_(np.arange(yc.shape[0]), nz, nz)] += np.einsum("cmg,cmh->cgh", yc, yc)

    @property
    def mean(self) -> np.ndarray:
        """Group means x̄, shape (S, C, G)."""
        n = np.maximum(self.count, 1).astype(np.float64)[:, None, None]
        return self.total / n

    def cov(self) -> np.ndarray:
        """Batch-means covariance of the group means, shape (S, C, G, G); inf below 2 batches."""
        n = self.count.astype(np.float64)
        b = self.blocks.astype(np.float64)
        m = self.mean * np.sqrt(n)[:, None, None]
        c = self.w2 - m[..., :, None] * m[..., None, :]
        few = b <= 1
        with np.errstate(invalid="ignore", divide="ignore"):
            c /= (n * (b - 1.0))[:, None, None, None]
        c[few] = np.inf
        return c


def lit_variance(d: np.ndarray, cov: np.ndarray) -> np.ndarray:
    """The variance dᵀCd of the levels ``d`` (G,) recombining groups of covariance ``cov`` (..., G, G),
    summed over the groups ``d`` lights only: a group whose error is unknown (inf, too few batches)
    adds nothing where it is off (not 0·inf = NaN) and inf where it is lit; 0 when nothing is lit.

    Notes
    -----
    Where every covariance is finite this is dᵀCd bit for bit: the terms of unlit groups are exact
    zeros, and einsum sums the rest in the same order (checked on random covariances)."""
    lit = np.flatnonzero(d)
    with np.errstate(invalid="ignore"):
        var = np.einsum("g,...gh,h->...", d[lit], cov[..., lit[:, None], lit[None, :]], d[lit])
    return np.where(np.isnan(var), np.inf, var)  # ±inf terms that cancel: still unknown
