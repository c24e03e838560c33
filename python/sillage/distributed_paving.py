"""Set inversion split over workers: the paving one process builds, built by many.

SIVIA's tree below a box depends only on that box (the test, the bisection rule and eps), never on
where the box sits in the tree. So the client runs SIVIA's first bisections itself (each a SIVIA of
the box cut short after a few boxes: the bisections are SIVIA's own, not a copy of its rule), sends
each box at the cut depth to a worker as a task, and grafts the sub-pavings into the top of the
tree (sillage.graft_pavings): the tree of one process: == to it, node for node. A box that SIVIA paves within the probe's few
boxes is kept as it is and sent nowhere.

A Function is compiled code and does not travel: a task carries the function as text (its variable
names and expression), compiled again on the worker.
"""
import math
import time
from dataclasses import dataclass

#: Boxes a probe may build before it is cut short: a box paved within them needs no task.
PROBE_BOXES = 63


@dataclass(frozen=True)
class InversionSpec:
    """What to invert, as text: X = f^-1(y) (kind 'sivia') or X = ker f for f in [lo, hi] ('kernel')."""

    kind: str
    variables: tuple
    expr: str  # f, or the lower bound function f- (kernel)
    y: object = None  # an Interval or IntervalVector (sivia)
    expr_hi: str = ""  # the upper bound function f+ (kernel)

    def run(self, box, eps, options):
        """The SiviaResult of this inversion over box (sivia_run or kernel_sivia_run)."""
        import sillage

        f = sillage.Function(list(self.variables), self.expr)
        if self.kind == "kernel":
            return sillage.kernel_sivia_run(box, f, sillage.Function(list(self.variables), self.expr_hi), eps, options)
        return sillage.sivia_run(box, f, self.y, eps, options)


InversionSpec.__init__.__doc__ = "An inversion from its fields, in order: kind, variables, expr, y, expr_hi."


def pave_box(spec, box, eps, max_boxes=None):
    """On a worker: the paving of box, one thread (the workers are the parallelism). Raises as sillage.sivia
    does when the budget is spent."""
    import sillage

    budget = sillage.Budget(max_boxes=max_boxes) if max_boxes else sillage.Budget()
    with sillage.ThreadLimit(1):
        return spec.run(box, eps, sillage.SiviaOptions(parallel=False, budget=budget)).take()


def _probe(spec, box, eps):
    """SIVIA of box cut short: ('paved', paving) if it ends within PROBE_BOXES, else ('split', left, right),
    the two boxes of its first bisection."""
    import sillage

    options = sillage.SiviaOptions(parallel=False, budget=sillage.Budget(max_boxes=PROBE_BOXES))
    result = spec.run(box, eps, options)
    if result.summary.status == sillage.Status.Converged or result.summary.status == sillage.Status.NoSolution:
        return ("paved", result.paving)
    p = result.paving
    if p.nb_nodes() < 3 or p.is_leaf(0):
        raise RuntimeError(f"distributed sivia: the probe of {box} stopped before its first bisection")
    return ("split", p.node_box(p.left(0)), p.node_box(p.right(0)))


def cut(spec, x0, eps, depth):
    """The tree of the first `depth` bisections of SIVIA over x0: ('paved', paving) | ('task', box) |
    ('node', box, left, right)."""
    if depth == 0:
        return ("task", x0)
    probe = _probe(spec, x0, eps)
    if probe[0] == "paved":
        return probe
    return ("node", x0, cut(spec, probe[1], eps, depth - 1), cut(spec, probe[2], eps, depth - 1))


def task_boxes(tree):
    """The boxes of the tree's tasks, in pre-order."""
    if tree[0] == "task":
        return [tree[1]]
    if tree[0] == "node":
        return task_boxes(tree[2]) + task_boxes(tree[3])
    return []


def top_paving(tree):
    """The paving of the tree with a Boundary leaf for each task, and those leaves' pre-order indices."""
    import sillage

    if tree[0] == "paved":
        return tree[1], []
    if tree[0] == "task":
        return sillage.leaf_paving(tree[1], sillage.PavingTag.Boundary), [0]
    (left, li), (right, ri) = top_paving(tree[2]), top_paving(tree[3])
    joined = sillage.join_pavings(tree[1], left, right)
    return joined, [1 + i for i in li] + [1 + left.nb_nodes() + i for i in ri]


def join(tree, pavings):
    """The paving of the tree with the tasks' pavings (in pre-order) in their places, in one pass."""
    import sillage

    top, leaves = top_paving(tree)
    return sillage.graft_pavings(top, leaves, list(pavings))


def default_depth(workers):
    """Enough tasks for the workers to share the load although subtrees differ in size: about 16 per worker."""
    return max(1, math.ceil(math.log2(16 * max(1, workers))))


def distributed_paving(client, spec, x0, eps, depth=None, max_boxes=None, progress=None, timings=None):
    """The paving of x0 for spec at eps, its subtrees paved as tasks on the client's cluster (timings: a dict
    given the tasks' time on the workers, 'task_seconds')."""
    import sillage

    from .distributed_run import run_tasks

    if depth is None:
        depth = default_depth(len(client.scheduler_info().get("workers", {})))
    x0 = sillage.IntervalVector(x0)
    tree = cut(spec, x0, eps, depth)
    boxes = task_boxes(tree)
    results = run_tasks(client, _pave_record, boxes, progress=progress, spec=spec, eps=eps, max_boxes=max_boxes)
    for r in results:
        if r["status"] == "error":
            raise RuntimeError(f"distributed sivia: a sub-box failed: {r['why']}")
    paving = join(tree, [r["paving"] for r in results])
    if timings is not None:
        timings["task_seconds"] = sum(r["seconds"] for r in results)
    return paving


def _pave_record(box, spec, eps, max_boxes):
    """run_tasks' record of one sub-paving (the paving travels pickled, bit for bit)."""
    start = time.perf_counter()
    paving = pave_box(spec, box, eps, max_boxes)
    return {"status": "solved", "paving": paving, "seconds": time.perf_counter() - start}
