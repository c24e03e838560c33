"""The synthetic bathymetric mission of thesis 7.3.2 (Daurade, 20 October 2015):
a generated seabed (Fig. 7.20), 5760 s of survey at 10 Hz (an overall crossing,
then north-south rails joined by keyhole turns, Fig. 7.16), sensors drawn inside
stated bounds, and the tubes a temporal SLAM starts from: the world velocity w
(7.31), the dead reckoning p from a start box (its drift, Fig. 7.17) and the
observation z = z_alt + z_depth + z_tide (7.30, Fig. 7.14).

Checks the truth inside p and z at every gate and slice. The stated sensor
bounds go through example_args.bound(), so a tightened run must fail."""
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import sillage
from example_args import bound, enclosure_ok, out_dir, print_result, run
from sillage.plot_bathymetry import plot_dem, plot_observation
from sillage.plot_tube import plot_thickness, plot_tube_vector_2d

SEED, DT = 7, 1.0  # the mission's seed; slice width of the tubes (s)


def stated_bounds():
    """The datasheet class of the sensors (see BathymetrySensorBounds), through bound()."""
    b = sillage.BathymetrySensorBounds()
    b.dvl_scale, b.dvl_offset = bound(0.002), bound(0.001)  # DVL 1200 kHz class
    b.heading, b.attitude = bound(0.05), bound(0.05)         # INS (deg)
    b.depth = bound(0.05)                                    # pressure (m)
    b.altitude_scale, b.altitude_offset = bound(0.01), bound(0.05)
    b.tide = bound(0.10)                                     # model (7.29) error (m)
    return b


def misses(tube, times, values):
    """Samples outside the tube: at the gates (time points) and in the slices."""
    td = tube.tdomain()
    tp = np.asarray(td.times())
    s = np.asarray(tube.slices_array())
    g = np.asarray(tube.gates_array())
    k = np.clip(np.searchsorted(tp, times, side="right") - 1, 0, len(s) - 1)
    out = (values < s[k, 0]) | (values > s[k, 1])
    on_gate = np.isin(times, tp)
    kg = np.searchsorted(tp, times[on_gate])
    out_g = (values[on_gate] < g[kg, 0]) | (values[on_gate] > g[kg, 1])
    return int(out.sum() + out_g.sum())


def main():
    out = out_dir(__doc__)
    opts = sillage.BathymetryMissionOptions()
    opts.bounds = stated_bounds()
    t0 = time.process_time()
    m = sillage.BathymetryMission(seed=SEED, options=opts)
    t_gen = time.process_time() - t0
    td = m.tdomain(DT)
    p = sillage.bathymetry_dead_reckoning(m, td, sillage.bathymetry_initial_box(m))
    z = sillage.bathymetry_observation_tube(m, td)
    N = td.nb_slices()
    pf = p.gate(N)
    diag = float(np.hypot(pf[0].diam(), pf[1].diam()))
    dem = m.dem
    depths = dem.depths()
    smooth = m.seabed.smooth_region[0].ub()
    cols = np.arange(dem.nx) * dem.cell_size
    print(f"Synthetic bathymetric mission (seed {SEED}): {m.options.duration:.0f} s, {m.nb_samples} samples, "
          f"path {m.path_length():.0f} m")
    print(f"  seabed {dem}: relief {dem.max_depth() - dem.min_depth():.2f} m, depth std "
          f"{depths[:, cols < smooth].std():.2f} m in the smooth strip, {depths[:, cols >= smooth].std():.2f} m beyond")
    print(f"  {m.seabed.bounds}")
    print(f"  {m.bounds}")
    print(f"  dead reckoning (dt = {DT} s): [p](t_f) widths {pf[0].diam():.1f} x {pf[1].diam():.1f} m, "
          f"diagonal {diag:.1f} m; generation {t_gen:.2f} s CPU")
    zt = sillage.bathymetry_truth_observation(m)
    times = m.times
    miss = (misses(p[0], times, m.x1) + misses(p[1], times, m.x2) + misses(p[2], times, m.truth.depth)
            + misses(z, times, np.asarray(zt.sample_values())))
    ok = enclosure_ok(p) and enclosure_ok(z) and miss == 0
    print(f"  truth inside p and z at every gate and slice: {'yes' if ok else 'NO'} ({miss} misses)")

    figures = []
    fig, ax = plt.subplots(figsize=(7, 6))
    plot_dem(ax, dem, m.x1, m.x2)
    ax.set_title("Seabed DEM and path (Fig. 7.20)")
    fig.savefig(out / "bathymetry_dem_py.png", dpi=110)
    figures.append(("bathymetry_dem_py.png", "Seabed DEM with the path (Fig. 7.20)"))
    fig, ax = plt.subplots(figsize=(7, 7))
    truth = sillage.bathymetry_truth(m)
    plot_tube_vector_2d(ax, p, 0, 1, color="#c8c8c8", edgecolor="#9a9a9a", truth=(truth[0], truth[1]))
    ax.set_title("Mission map: dead reckoning and truth (Fig. 7.16)")
    ax.set_aspect("equal")
    fig.savefig(out / "bathymetry_map_py.png", dpi=110)
    figures.append(("bathymetry_map_py.png", "Mission map: dead-reckoning tube and truth (Fig. 7.16)"))
    fig, ax = plt.subplots(figsize=(8, 3))
    plot_thickness(ax, p.subvector(0, 1), measure=sillage.ThicknessMeasure.Diagonal)
    ax.set_title("Dead-reckoning thickness (Fig. 7.17)")
    fig.savefig(out / "bathymetry_thickness_py.png", dpi=110)
    figures.append(("bathymetry_thickness_py.png", "Dead-reckoning thickness d(t) (Fig. 7.17)"))
    fig, ax = plt.subplots(figsize=(9, 3.5))
    plot_observation(ax, z, (zt.sample_times(), zt.sample_values()))
    ax.set_title("Observation tube (Fig. 7.14)")
    fig.savefig(out / "bathymetry_observation_py.png", dpi=110)
    figures.append(("bathymetry_observation_py.png", "Observation tube [z](t) and truth (Fig. 7.14)"))
    plt.close("all")
    print_result("bathymetry_mission",
                 f"path {m.path_length():.0f} m, relief {dem.max_depth() - dem.min_depth():.1f} m, "
                 f"DR diagonal {diag:.1f} m at t_f, truth inside: {'yes' if ok else 'no'}", ok, figures)


if __name__ == "__main__":
    run(main)
