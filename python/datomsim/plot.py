"""Pictures of a sweep's rows (datomsim.sweep, docs/python.md): how often the runs succeeded and
how long they took, against one input, as a matplotlib figure."""

from __future__ import annotations

import statistics
from collections import defaultdict
from typing import Iterable, Optional


def sweep_figure(rows: Iterable[dict], x: str = "modules", group: Optional[str] = "program",
                 metric: str = "makespan_s", title: Optional[str] = None):
    """Two panels against ``x``: the success rate, and the median ``metric`` of the runs that
    succeeded (with the range from the lowest to the highest), one line per value of ``group``.
    Returns the Figure; ``figure.savefig("sweep.png")`` writes it."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    by_line: dict = defaultdict(lambda: defaultdict(list))
    for row in rows:
        if row.get(x) in (None, ""):
            continue
        by_line[row.get(group, "") if group else ""][row[x]].append(row)
    if not by_line:
        raise ValueError(f"no row has a value for {x!r}")

    figure, (rates, values) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for line, by_x in sorted(by_line.items(), key=lambda item: str(item[0])):
        xs = sorted(by_x)
        rate = [100 * sum(1 for r in by_x[v] if r.get("success")) / len(by_x[v]) for v in xs]
        label = f"{line} ({sum(len(by_x[v]) for v in xs)} runs)" if line != "" else None
        rates.plot(xs, rate, marker="o", label=label)
        done = [(v, [float(r[metric]) for r in by_x[v] if r.get("success") and r.get(metric) != ""])
                for v in xs]
        done = [(v, m) for v, m in done if m]
        if done:
            middle = [statistics.median(m) for _, m in done]
            low = [min(m) for _, m in done]
            high = [max(m) for _, m in done]
            points = [v for v, _ in done]
            values.plot(points, middle, marker="o", label=label)
            values.fill_between(points, low, high, alpha=0.2)
    rates.set_title("success rate")
    rates.set_xlabel(x)
    rates.set_ylabel("runs that succeeded (%)")
    rates.set_ylim(-5, 105)
    rates.grid(alpha=0.3)
    values.set_title("successful runs: median and range")
    values.set_xlabel(x)
    values.set_ylabel(metric)
    values.grid(alpha=0.3)
    if any(line != "" for line in by_line):
        rates.legend()
    figure.suptitle(title or f"{sum(len(v) for b in by_line.values() for v in b.values())} runs")
    return figure
