"""sillage.distributed.sivia / kernel_sivia: the subtrees of SIVIA's first bisections paved as tasks
on a real local cluster and joined, == to the paving of one process (same nodes, same boxes bit for
bit, same tags); Paving pickles bit for bit; join_pavings and leaf_paving build trees from pieces."""
import pickle

import pytest

import sillage

pytest.importorskip("distributed")
from sillage import distributed  # noqa: E402
from sillage.distributed_paving import InversionSpec, cut, join, pave_box, task_boxes  # noqa: E402

RING = (["x", "y"], "x^2 + y^2", sillage.Interval(1, 2))


def local(x0, eps):
    f = sillage.Function(RING[0], RING[1])
    return sillage.sivia(sillage.IntervalVector(x0), f, RING[2], eps, sillage.SiviaOptions(parallel=False))


def test_a_paving_pickles_bit_for_bit():
    p = local([[-2, 2], [-2, 2]], 0.1)
    q = pickle.loads(pickle.dumps(p))
    assert q == p and q.nb_nodes() == p.nb_nodes() and q.count(sillage.PavingTag.Inner) > 0


def test_join_puts_pieces_under_a_root():
    box = sillage.IntervalVector([[0, 2], [0, 1]])
    left = sillage.leaf_paving(sillage.IntervalVector([[0, 1], [0, 1]]), sillage.PavingTag.Inner)
    right = sillage.leaf_paving(sillage.IntervalVector([[1, 2], [0, 1]]), sillage.PavingTag.Outside)
    p = sillage.join_pavings(box, left, right)
    assert p.nb_nodes() == 3 and p.domain() == box and p.left(0) == 1 and p.right(0) == 2
    assert p.tag(1) == sillage.PavingTag.Inner and p.tag(2) == sillage.PavingTag.Outside
    with pytest.raises(sillage.Error, match="not inside the box"):
        sillage.join_pavings(sillage.IntervalVector([[0, 1], [0, 1]]), left, right)


def test_graft_replaces_leaves_by_pavings():
    box = sillage.IntervalVector([[0, 2], [0, 1]])
    halves = [sillage.IntervalVector([[0, 1], [0, 1]]), sillage.IntervalVector([[1, 2], [0, 1]])]
    top = sillage.join_pavings(box, *(sillage.leaf_paving(h, sillage.PavingTag.Boundary) for h in halves))
    ring = [local(h, 0.1) for h in halves]
    grafted = sillage.graft_pavings(top, [1, 2], ring)
    assert grafted == sillage.join_pavings(box, *ring)
    assert grafted.nb_nodes() == 1 + ring[0].nb_nodes() + ring[1].nb_nodes()
    with pytest.raises(sillage.Error, match="expected the box of leaf 2"):
        sillage.graft_pavings(top, [1, 2], [ring[0], ring[0]])
    with pytest.raises(sillage.Error, match="is not a leaf"):
        sillage.graft_pavings(top, [0], [ring[0]])


def test_the_cut_follows_sivia_own_bisections():
    """Cut at depth 3 and joined locally (no cluster), the paving is the one of a single run."""
    spec = InversionSpec("sivia", tuple(RING[0]), RING[1], y=RING[2])
    x0 = sillage.IntervalVector([[-2, 2], [-2, 2]])
    tree = cut(spec, x0, 0.05, 3)
    joined = join(tree, [pave_box(spec, b, 0.05) for b in task_boxes(tree)])
    assert len(task_boxes(tree)) == 8 and joined == local(x0, 0.05)


def test_distributed_sivia_equals_one_process(dask_client):
    x0 = [[-2, 2], [-2, 2.5]]
    p = distributed.sivia(x0, RING[0], RING[1], RING[2], 0.02, client=dask_client, depth=4)
    assert p == local(x0, 0.02)


def test_distributed_kernel_sivia_equals_one_process(dask_client):
    x0 = sillage.IntervalVector([[-2, 2], [-1, 1]])
    lo, hi = "y - sin(x) - 0.1", "y - sin(x) + 0.1"
    p = distributed.kernel_sivia(x0, ["x", "y"], lo, hi, 0.02, client=dask_client, depth=3)
    one = sillage.kernel_sivia(x0, sillage.Function(["x", "y"], lo), sillage.Function(["x", "y"], hi), 0.02,
                               sillage.SiviaOptions(parallel=False))
    assert p == one and p.count(sillage.PavingTag.Inner) > 0


def test_a_box_paved_by_the_probe_needs_no_task():
    """A box SIVIA decides at once (outside the ring) is kept from the probe: no task."""
    spec = InversionSpec("sivia", tuple(RING[0]), RING[1], y=RING[2])
    tree = cut(spec, sillage.IntervalVector([[5, 6], [5, 6]]), 0.01, 4)
    assert tree[0] == "paved" and task_boxes(tree) == []
