#!/usr/bin/python3
"""hemirad's figures (src/output/Figure.h): reads a JSON list of figures, writes each as SVG and PDF.

hemirad computes the data and runs this script (installed as share/hemirad/python/plot.py); the
figures are drawn by matplotlib (Debian python3-matplotlib). Output is deterministic: fixed SVG
hash salt, no dates, so the same data gives the same bytes. Fonts travel with the figure (SVG text
as outlines, TrueType embedded in the PDF), and the title lives only in the metadata: a paper's
caption names the figure. Every figure carries the run's
provenance (version, git hash, command line, backend, renderer) in its SVG and PDF metadata.

  plot.py --check        exits 0 if matplotlib imports (hemirad's check before long work)
  plot.py SPEC.json      draws the figures SPEC.json lists

A figure: {"svg": PATH, "pdf": PATH, "kind": "lines" | "heatmap", "title": ..., "provenance": TEXT, ...}
  lines:   "x_label", "y_label", "log_x", "log_y", "series": [{"label", "x": [...], "y": [...]}]
  heatmap: "values": rows of numbers (null: no data), "colour_label", "log" (log colour scale),
           "vmin", "vmax"; or "classes": [{"label", "colour"}] with values the class indices
"""
import json
import sys


def setup():
    import matplotlib
    matplotlib.use("svg")  # no display; PDF comes from the same figure
    matplotlib.rcParams.update({"svg.hashsalt": "hemirad", "svg.fonttype": "path", "pdf.fonttype": 42,
                                "font.family": "DejaVu Sans", "font.size": 9, "figure.dpi": 100,
                                "path.simplify": False})
    return matplotlib


def lines(fig, spec):
    ax = fig.add_subplot()
    markers = "os^Dv<>p"
    for k, s in enumerate(spec["series"]):
        pts = [(x, y) for x, y in zip(s["x"], s["y"])
               if (x > 0 or not spec.get("log_x")) and (y > 0 or not spec.get("log_y"))]
        if not pts:
            continue
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=markers[k % len(markers)], markersize=4,
                linewidth=1.5, label=s["label"])
    if spec.get("log_x"):
        ax.set_xscale("log")
    elif all(float(x).is_integer() for s in spec["series"] for x in s["x"]):
        from matplotlib.ticker import MaxNLocator
        ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # levels, counts: no 0.25 ticks
    if spec.get("log_y"):
        ax.set_yscale("log")
    ax.set_xlabel(spec["x_label"])
    ax.set_ylabel(spec["y_label"])
    ax.grid(True, which="major", color="#dddddd", linewidth=0.6)
    if spec["series"]:
        ax.legend(fontsize=8)


def heatmap(fig, spec):
    import numpy as np
    from matplotlib import colors
    ax = fig.add_subplot()
    values = np.array([[np.nan if v is None else v for v in row] for row in spec["values"]], dtype=float)
    ax.set_xlabel(spec.get("x_label", "atlas texel x"))
    ax.set_ylabel(spec.get("y_label", "atlas texel y"))
    if "classes" in spec:
        cmap = colors.ListedColormap([c["colour"] for c in spec["classes"]])
        n = len(spec["classes"])
        image = ax.imshow(values, cmap=cmap, vmin=-0.5, vmax=n - 0.5, interpolation="nearest", origin="lower")
        bar = fig.colorbar(image, ax=ax, ticks=range(n))
        bar.ax.set_yticklabels([c["label"] for c in spec["classes"]])
    else:
        cmap = matplotlib.colormaps["viridis"].copy()
        cmap.set_bad("#000000")
        lo, hi = spec.get("vmin"), spec.get("vmax")
        norm = colors.LogNorm(lo, hi, clip=True) if spec.get("log") else colors.Normalize(lo, hi, clip=True)
        image = ax.imshow(values, cmap=cmap, norm=norm, interpolation="nearest", origin="lower")
        fig.colorbar(image, ax=ax, label=spec.get("colour_label", ""))


def draw(spec):
    from matplotlib.figure import Figure
    width, height = spec.get("size", [6.4, 4.2])
    fig = Figure(figsize=(width, height), layout="constrained")
    (lines if spec["kind"] == "lines" else heatmap)(fig, spec)  # no title drawn: the caption's job
    meta = {"Title": spec["title"], "Creator": "hemirad", "Description": spec["provenance"]}
    fig.savefig(spec["svg"], format="svg", metadata={**meta, "Date": None})
    fig.savefig(spec["pdf"], format="pdf", metadata={"Title": spec["title"], "Creator": "hemirad",
                                                     "Subject": spec["provenance"], "Producer": None,
                                                     "CreationDate": None})


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: plot.py --check | plot.py SPEC.json")
    try:
        matplotlib = setup()
    except ImportError as e:
        sys.exit(f"{sys.executable}: {e}")  # hemirad prints it after what is missing
    if sys.argv[1] != "--check":
        with open(sys.argv[1], encoding="utf-8") as f:
            for figure in json.load(f):
                draw(figure)
