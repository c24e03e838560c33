"""The outputs of a batch or a sweep: one table (results.csv, results.json) and one report.html.

The report holds the table, for a sweep one figure per swept key (the mean thickness and the share of
the truth inside against that key's values, a line per combination of the other keys) and the map
of each task whose map was asked for. Figures are matplotlib PNGs inside the page: one offline file.
"""
import base64
import csv
import html
import io
import json
import os
import tomllib

#: The columns of results.csv before the swept keys and the widths of the variables.
COLUMNS = ["index", "file", "status", "truth_inside", "truth_samples", "truth_fraction", "mean_thickness",
           "delta", "slices", "seconds", "solve_seconds", "worker", "why"]


def _variables(records):
    return sorted({name for r in records for name in (r.get("widths") or {})})


def _keys(records):
    keys = []
    for r in records:
        keys += [k for k in r.get("settings", {}) if k not in keys]
    return keys


def _swept(records, keys):
    """The keys set to more than one value (a key set to one value in every task is no axis)."""
    return [k for k in keys if len({r.get("settings", {}).get(k) for r in records}) > 1]


def table_rows(records):
    """One flat dict per record: COLUMNS, the swept keys, then 'width NAME' per variable."""
    keys, names = _keys(records), _variables(records)
    rows = []
    for r in records:
        row = {c: r.get(c) for c in COLUMNS}
        row.update({k: r.get("settings", {}).get(k) for k in keys})
        row.update({f"width {n}": (r.get("widths") or {}).get(n) for n in names})
        rows.append(row)
    return rows


def write_table(records, folder):
    """folder/results.csv and folder/results.json (the records without their maps)."""
    os.makedirs(folder, exist_ok=True)
    rows = table_rows(records)
    with open(os.path.join(folder, "results.csv"), "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]) if rows else COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(folder, "results.json"), "w", encoding="utf-8") as f:
        json.dump([{k: v for k, v in r.items() if k != "maps"} for r in records], f, indent=1)


def _number(text):
    """A swept TOML value as a number for an axis; None if it is not one."""
    try:
        v = tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return None
    return float(v) if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _png(fig):
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    return base64.b64encode(buf.getvalue()).decode("ascii")


def _sweep_figure(records, key, keys):
    """Mean thickness and truth inside against the values of key, a line per setting of the other keys."""
    import matplotlib.pyplot as plt

    values = list(dict.fromkeys(r["settings"][key] for r in records))
    numbers = [_number(v) for v in values]
    numeric = all(n is not None for n in numbers)
    position = dict(zip(values, numbers if numeric else range(len(values))))
    others = [k for k in keys if k != key]
    lines = {}
    for r in records:
        if r.get("status") not in ("solved", "stopped"):
            continue
        name = " ".join(f"{k}={r['settings'][k]}" for k in others) or key
        lines.setdefault(name, []).append(r)
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.6))
    for name, rs in lines.items():
        rs = sorted(rs, key=lambda r: position[r["settings"][key]])
        xs = [position[r["settings"][key]] for r in rs]
        a1.plot(xs, [r["mean_thickness"] for r in rs], "o-", label=name)
        if any(r.get("truth_fraction") is not None for r in rs):
            a2.plot(xs, [r.get("truth_fraction") for r in rs], "o-", label=name)
    for ax, title in ((a1, "mean thickness of the tubes"), (a2, "share of the truth inside")):
        ax.set_xlabel(key)
        ax.set_title(title)
        if not numeric:
            ax.set_xticks(range(len(values)), values, rotation=30)
    a2.set_ylim(-0.05, 1.05)
    if len(lines) > 1:
        a1.legend(fontsize=7)
    plt.close(fig)
    return _png(fig)


def _map_figure(record):
    """The task's map: each variable of its [output] maps (or plots) in the plane (tube vectors) or
    against t (tubes)."""
    import matplotlib.pyplot as plt

    import sillage
    from .plot_tube import plot_tube, plot_tube_vector_2d

    maps = record["maps"]
    fig, axes = plt.subplots(1, len(maps), figsize=(5 * len(maps), 4.5), squeeze=False)
    for ax, (name, value) in zip(axes[0], maps.items()):
        if isinstance(value, sillage.TubeVector) and len(value) >= 2:
            plot_tube_vector_2d(ax, value)
            ax.set_aspect("equal", adjustable="datalim")
        else:
            plot_tube(ax, value if isinstance(value, sillage.Tube) else value[0])
        ax.set_title(name)
    fig.suptitle(record.get("label", ""), fontsize=9)
    plt.close(fig)
    return _png(fig)


def _html_table(rows):
    head = "".join(f"<th>{html.escape(str(c))}</th>" for c in rows[0]) if rows else ""

    def cell(v):
        return f"{v:.4g}" if isinstance(v, float) else ("" if v is None else str(v))

    body = "".join("<tr>" + "".join(f"<td>{html.escape(cell(v))}</td>" for v in row.values()) + "</tr>"
                   for row in rows)
    return f"<table><tr>{head}</tr>{body}</table>"


def write_report(records, folder, title, wall_seconds=None):
    """folder/report.html (and the table, write_table): the page path."""
    import matplotlib

    matplotlib.use("Agg")
    write_table(records, folder)
    keys = _swept(records, _keys(records))
    counts = {}
    for r in records:
        counts[r["status"]] = counts.get(r["status"], 0) + 1
    summary = ", ".join(f"{n} {s}" for s, n in sorted(counts.items()))
    if wall_seconds is not None:
        summary += f"; {len(records)} tasks in {wall_seconds:.1f} s"
    parts = [f"<h1>{html.escape(title)}</h1>", f"<p>{html.escape(summary)}</p>"]
    for key in keys:
        parts.append(f"<h2>{html.escape(key)}</h2><img src='data:image/png;base64,{_sweep_figure(records, key, keys)}'>")
    for r in records:
        if r.get("maps"):
            parts.append(f"<h2>task {r['index']}: {html.escape(r['label'])}</h2>"
                         f"<img src='data:image/png;base64,{_map_figure(r)}'>")
    parts.append("<h2>results</h2>" + _html_table(table_rows(records)))
    style = ("body{font-family:sans-serif;margin:2em}table{border-collapse:collapse;font-size:12px}"
             "td,th{border:1px solid #ccc;padding:2px 6px}")
    page = f"<!doctype html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>" \
           f"<style>{style}</style></head><body>{''.join(parts)}</body></html>"
    path = os.path.join(folder, "report.html")
    with open(path, "w", encoding="utf-8") as f:
        f.write(page)
    return path
