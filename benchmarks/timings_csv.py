"""benchmarks/results/timings.csv: one row per measured figure, with the
machine, CPU, commit and date it was measured on. A new measurement of a
figure (same table and quantity) replaces the old row; scripts/doc_tables.py
turns each table's rows into the docs' tables."""
import csv
import datetime
import os
import platform
import subprocess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
PATH = os.path.join(ROOT, "benchmarks", "results", "timings.csv")
COLUMNS = ["machine", "cpu", "commit", "date", "table", "command", "quantity", "value", "unit", "note"]


def machine():
    return f"{os.cpu_count()} cores, {platform.machine()}"


def cpu():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "?"


def commit(source=ROOT):
    """The commit of `source`, with "+" when its code differs from it."""
    head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=source, capture_output=True, text=True)
    dirty = subprocess.run(["git", "diff", "--quiet", "HEAD", "--", ".", ":!docs", ":!README.md",
                            ":!benchmarks/results"], cwd=source).returncode
    return head.stdout.strip() + ("+" if dirty else "")


def load():
    with open("/proc/loadavg", encoding="utf-8") as f:
        return float(f.read().split()[0])


def record(rows, at_commit=None):
    """rows: dicts with table, command, quantity, value, unit, note."""
    old = []
    if os.path.exists(PATH):
        with open(PATH, encoding="utf-8") as f:
            old = list(csv.DictReader(f))
    new_keys = {(r["table"], r["quantity"]) for r in rows}
    stamp = {"machine": machine(), "cpu": cpu(), "commit": at_commit or commit(),
             "date": datetime.date.today().isoformat()}
    kept = [r for r in old if (r["table"], r["quantity"]) not in new_keys]
    with open(PATH, "w", newline="", encoding="utf-8") as f:
        w = csv.DictWriter(f, COLUMNS)
        w.writeheader()
        w.writerows(kept + [{**stamp, **r} for r in rows])
