"""The statistics of small ensembles that problem3.py's width tables use (numpy only): the
difference of two ensembles' means with its standard error, the weighted fit of ensemble means
against a parameter, and the exact permutation test of the one-way layout."""
import itertools

import numpy as np


def mean_difference(a, b):
    """(mean of @p b minus mean of @p a, the standard error of that difference), per column of the
    ensembles' widths @p a, @p b [runs, (elements' F, averaged F)]."""
    se = np.sqrt(a.var(axis=0, ddof=1) / len(a) + b.var(axis=0, ddof=1) / len(b))
    return b.mean(axis=0) - a.mean(axis=0), se


def linear_fit(x, widths):
    """[(field, ((a, its standard error), (b, its standard error), chi^2))] of the ensembles' mean
    widths against @p x, w = a + b x, fitted by least squares weighted with the means' standard
    errors (@p widths: per ensemble an array [runs, (elements' F, averaged F)] in mm); chi^2 against
    its len(x) - 2 degrees of freedom says whether the means are linear in x."""
    fits = []
    for col, name in enumerate(("elements' F", "averaged F")):
        mean = np.array([w[:, col].mean() for w in widths])
        se = np.array([w[:, col].std(ddof=1) / np.sqrt(len(w)) for w in widths])
        X = np.column_stack([np.ones_like(x), x]) / se[:, None]
        cov = np.linalg.inv(X.T @ X)
        a, b = cov @ X.T @ (mean / se)
        chi2 = float(np.sum(((mean - a - b * x) / se) ** 2))
        fits.append((name, ((a, np.sqrt(cov[0, 0])), (b, np.sqrt(cov[1, 1])), chi2)))
    return fits


def between_steps(groups):
    """The between-group sum of squares of @p groups (arrays of widths), the one-way layout's
    statistic for a fixed pooled set (the F ratio grows with it)."""
    grand = np.concatenate(groups).mean()
    return sum(len(g) * (g.mean() - grand) ** 2 for g in groups)


def permutation_p(groups):
    """(reached, total): of every split of the pooled values of @p groups (arrays) into groups of
    their sizes, how many have a between-group sum of squares (between_steps) at least the measured
    one; reached / total is the exact p value that the grouping does not matter."""
    pooled = np.concatenate(groups)
    measured = between_steps(groups)
    reached = total = 0
    for split in splits(list(range(len(pooled))), [len(g) for g in groups]):
        total += 1
        reached += between_steps([pooled[list(g)] for g in split]) >= measured * (1 - 1e-12)
    return reached, total


def splits(items, sizes):
    """Every split of @p items into groups of @p sizes, in order (the groups as tuples)."""
    if len(sizes) == 1:
        yield (tuple(items),)
        return
    for first in itertools.combinations(items, sizes[0]):
        rest = [i for i in items if i not in first]
        for tail in splits(rest, sizes[1:]):
            yield (first, *tail)
