"""matplotlib helpers for the synthetic bathymetric mission (thesis 7.3):
the DEM with the path (Fig. 7.20) and the observation tube with its truth
(Fig. 7.14). The mission map and the thickness graph use plot_tube."""
import numpy as np


def plot_dem(ax, dem, x=None, y=None, cmap="viridis_r", path_color="white", colorbar=True):
    """The DEM's node depths as an image (deep = dark with the default map), the path (x, y)
    over it. Returns the image."""
    d = dem.domain()
    h = dem.cell_size
    extent = (d[0].lb() - h / 2, d[0].ub() + h / 2, d[1].lb() - h / 2, d[1].ub() + h / 2)
    im = ax.imshow(dem.depths(), origin="lower", extent=extent, cmap=cmap, interpolation="bilinear")
    if x is not None and y is not None:
        ax.plot(np.asarray(x), np.asarray(y), color=path_color, linewidth=0.7)
    ax.set_xlabel("east (m)")
    ax.set_ylabel("north (m)")
    ax.set_aspect("equal")
    if colorbar:
        ax.figure.colorbar(im, ax=ax, label="depth (m)")
    return im


def plot_observation(ax, z, truth=None, color="#a9cdf2", truth_color="#d62728", max_points=4000):
    """The observation tube [z](t) as its slice band (decimated to at most max_points columns,
    each the hull of the slices it covers) and the true observation (times, values)."""
    t = np.asarray(z.tdomain().times(), dtype=float)
    s = np.asarray(z.slices_array(), dtype=float)
    n = len(s)
    lo, hi = s[:, 0], s[:, 1]
    step = max(1, n // max_points)
    idx = np.arange(0, n, step)
    lo_h = np.minimum.reduceat(lo, idx)
    hi_h = np.maximum.reduceat(hi, idx)
    ends = np.append(idx[1:], n)
    ts = np.column_stack([t[idx], t[ends]]).ravel()
    ax.fill_between(ts, np.repeat(lo_h, 2), np.repeat(hi_h, 2), color=color, linewidth=0, label="[z](t)")
    if truth is not None:
        ax.plot(truth[0], truth[1], color=truth_color, linewidth=0.8, label="truth")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("z (m)")
    ax.legend(loc="upper right")
