"""The CMU Plaza 1 data (../shared/data/plaza1, read in place; README there), as
examples/cpp/plaza1_data.h reads it: an INS/GPS ground truth, one odometry increment per
ground-truth step and the radio ranges to 4 beacons. Shared by the plaza1 examples. A file
that does not fit (a row count, a time stamp, an unknown beacon) is a sillage.Error naming the
file and line: bad input, exit 2 (example_args.run)."""
import sillage
from sillage import CsvTable

# The files of the data set, checked by example_args.out_dir_and_data.
FILES = ("ground_truth.csv", "odometry.csv", "ranges.csv", "beacons.csv")


def load(folder):
    """A dict: the ground truth t, x, y, heading (heading wrapped to (-pi, pi]); per step k (over
    [t_k, t_{k+1}]) the odometer distance dist and two heading changes: dpsi_ins equals the
    ground-truth increments (an INS-quality heading), dpsi_drift drifts like a real gyro (also as
    dpsi); the ranges rt (time), rid (beacon id), r (metres); beacons {id: (x, y)}."""
    gt, odo = CsvTable.read(str(folder / "ground_truth.csv")), CsvTable.read(str(folder / "odometry.csv"))
    rg, bc = CsvTable.read(str(folder / "ranges.csv")), CsvTable.read(str(folder / "beacons.csv"))
    d = dict(t=gt.values("t_s"), x=gt.values("x_m"), y=gt.values("y_m"), heading=gt.values("heading_rad"),
             dist=odo.values("delta_dist_m"), dpsi_ins=odo.values("delta_heading_rad"),
             dpsi_drift=odo.values("delta_heading_drp_rad"),
             rt=rg.values("t_s"), rid=rg.values("beacon_id"), r=rg.values("range_m"),
             beacons={int(i): (x, y) for i, x, y in zip(bc.values("beacon_id"), bc.values("x_m"), bc.values("y_m"))})
    d["dpsi"] = d["dpsi_drift"]  # the heading of the networks and of the bound audit
    ot = odo.values("t_s")
    if len(ot) + 1 != len(d["t"]) or len(ot) == 0:
        raise sillage.Error(f"{odo.source()}: {len(ot)} rows, expected one per step of {gt.source()} "
                            f"({len(d['t'])} rows, at least 2)")
    for k, t in enumerate(ot):
        if t != d["t"][k + 1]:
            raise sillage.Error(f"{odo.where(k)}: t_s = {t:g}, expected the end of its step, {d['t'][k + 1]:g} "
                                f"({gt.where(k + 1)})")
    for j, i in enumerate(d["rid"]):
        if i != int(i) or int(i) not in d["beacons"]:
            raise sillage.Error(f"{rg.where(j)}: beacon {i:g} is not in {bc.source()}")
    return d
