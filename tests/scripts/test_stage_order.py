"""The order in which the studies start stages side by side
(bin/darcydem/case.py: start_order, makespan, used by run_side_by_side):
on jobs workers that each take the next stage when free, the chosen order
ends no later than any other, so no later than longest first; for the quick
shear's five stages it is the best split of their costs over two workers
(the three saturated shears of 3.909 s of simulated time, at a dry cost of
0.94 for the dry one, and the two rate-series stages of 2.345 s: the dry
stage beside the rate series ends at 3.674 + 2 x 2.345 = 8.364, where longest
first leaves one rate-series stage alone at the end, 3.909 + 2 x 2.345 =
8.599). Equal costs keep the given order. Each stage side by side gets its
share of the cores, its MPI ranks counted (threads_per_stage): no more DEM
threads in all than cores."""

import itertools
import random

import pytest

import darcydem.case
from darcydem.case import makespan, ranks_for_solvers, run_side_by_side, start_order


def best_split(costs):
    """The soonest end of costs on two workers: the best partition, by
    brute force over the subsets (any order realises a partition's end at
    best)."""
    total = sum(costs)
    return min(max(sum(s), total - sum(s))
               for r in range(len(costs) + 1) for s in itertools.combinations(costs, r))


def test_makespan_of_a_queue():
    # two workers: 3 and 2 start; 1 goes to the one free at 2, 4 to the one free at 3
    assert makespan([3.0, 2.0, 1.0, 4.0], [0, 1, 2, 3], 2) == pytest.approx(7.0)
    assert makespan([3.0, 2.0, 1.0, 4.0], [0, 1, 2, 3], 1) == pytest.approx(10.0)


def test_quick_shear_stages_are_split_best():
    dry = 0.94 * 3.909
    costs = [3.909, 3.909, dry, 2.345, 2.345]  # permeable, impermeable, dry, rate series
    order = start_order(costs, 2)
    assert sorted(order) == list(range(5))
    assert makespan(costs, order, 2) == pytest.approx(best_split(costs), rel=1e-12)
    assert makespan(costs, order, 2) == pytest.approx(dry + 2 * 2.345, rel=1e-12)
    assert makespan(costs, range(5), 2) == pytest.approx(3.909 + 2 * 2.345, rel=1e-12)


def test_never_later_than_longest_first():
    rng = random.Random(7)
    for _ in range(30):
        n, jobs = rng.randint(2, 7), rng.randint(2, 3)
        costs = [rng.uniform(0.5, 4.0) for _ in range(n)]
        order = start_order(costs, jobs)
        assert sorted(order) == list(range(n))
        longest_first = sorted(range(n), key=lambda k: -costs[k])
        assert makespan(costs, order, jobs) <= makespan(costs, longest_first, jobs) + 1e-12
        assert makespan(costs, order, jobs) >= max(max(costs), sum(costs) / jobs) - 1e-12


def test_equal_costs_keep_the_given_order():
    assert start_order([2.0, 2.0, 2.0, 2.0], 2) == [0, 1, 2, 3]
    # beyond the exhaustive search: longest first, ties in the given order
    assert start_order([1.0, 3.0, 1.0, 3.0], 2, exhaustive_up_to=2) == [1, 3, 0, 2]


@pytest.mark.parametrize("cores, ranks, jobs, stages, threads", [
    (2, 1, 2, 5, 1),   # the quick shear on 2 cores: two 1-thread stages
    (4, 1, 2, 5, 2),
    (4, 2, 2, 5, 1),   # 2 stages x 2 ranks x 1 thread on 4 cores (not 2 threads: 8 on 4)
    (8, 2, 2, 5, 2),
    (4, 1, 8, 3, 1),   # more jobs than stages: the stages share the cores
    (4, 1, 4, 2, 2),
    (2, 2, 2, 5, 1),   # oversubscribed by the ranks alone: still one thread
])
def test_side_by_side_stages_share_the_cores(monkeypatch, cores, ranks, jobs, stages, threads):
    monkeypatch.setattr(darcydem.case, "usable_cores", lambda: cores)
    with ranks_for_solvers(ranks):
        got = run_side_by_side([lambda t: t] * stages, jobs, lambda message: None, "stages")
    assert got == [threads] * stages
    assert min(jobs, stages) * ranks * threads <= max(cores, min(jobs, stages) * ranks)
