#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Coverage of the printed uncertainties on the development corpus
# (bench/coverage/corpus/*.json: published or exact-answer grid series, each
# with a reference answer and its source). Every window of at least 4 and at
# most n − 1 consecutive grids of every series is extrapolated with
# `gridfree extrapolate --json`; f₁ ± U₁ (the window's finest grid) and
# f0 ± U₀ are compared with the series' reference. Counted per the window's
# own verdict, per source and over the whole corpus
# (docs/EXTRAPOLATION.md "Coverage on other codes' series").
#
#   bench/coverage/corpus.py GRIDFREE [--estimators averaged,capped,...] [--source FILE-STEM]
#                                     [--windows] [--series] [--misses VERDICT]
#
# Estimators: the library methods averaged, capped, fm, eh14 as they are; the
# same with each series' declared formal order (averaged+order: `--order P`);
# the methods before the bias checks (capped-before: `--no-leave-one-out`)
# and averaged before its floor on unreliable windows (`--no-range-floor`);
# and the prototypes of candidates.py (names listed by --help). About 50 s
# for the eight library estimators on the 1 165 windows of 2026-12-07 on a
# 2-core machine; the bootstrap prototypes take minutes.
import argparse
import glob
import json
import os
import statistics
import sys

import candidates

HERE = os.path.dirname(os.path.abspath(__file__))


def load_corpus(stems):
    sources = []
    for path in sorted(glob.glob(os.path.join(HERE, "corpus", "*.json"))):
        stem = os.path.splitext(os.path.basename(path))[0]
        if stems and stem not in stems:
            continue
        doc = json.load(open(path))
        for s in doc["series"]:
            pts = sorted(zip(s["h"], s["f"]))
            s["h"], s["f"] = [p[0] for p in pts], [p[1] for p in pts]
        sources.append((stem, doc))
    return sources


def windows(series):
    """Every run of m consecutive grids, 4 ≤ m ≤ n − 1 (h ascending)."""
    n = len(series["h"])
    for m in range(4, n):
        for first in range(0, n - m + 1):
            yield series["h"][first:first + m], series["f"][first:first + m]


class Tally:
    def __init__(self):
        self.n = self.cov1 = self.cov0 = self.judged0 = 0
        self.width, self.worst, self.worst_at = [], 0.0, ""

    def add(self, w, ref, label):
        self.n += 1
        miss = abs(ref - w["f1"])
        self.cov1 += miss <= w["u1"]
        if w.get("u0") is not None:
            self.judged0 += 1
            self.cov0 += abs(ref - w["f0"]) <= w["u0"]
        if w["f1"] != 0:
            self.width.append(w["u1"] / abs(w["f1"]))
        units = miss / w["u1"] if w["u1"] > 0 else (0.0 if miss == 0 else float("inf"))
        if units > self.worst:
            self.worst, self.worst_at = units, label


def pct(k, n):
    return "%d/%d (%.0f %%)" % (k, n, 100.0 * k / n) if n else "–"


def table(title, tallies, show_worst_at):
    print("\n### " + title + "\n")
    print("| estimator | verdict | windows | f₁ ± U₁ covers | f0 ± U₀ covers | median U₁/|f₁| | worst miss (U₁) |")
    print("|---|---|---|---|---|---|---|")
    for (est, verdict), t in sorted(tallies.items()):
        if not t.n:
            continue
        worst = "%.2f" % t.worst + (" (%s)" % t.worst_at if show_worst_at and t.worst > 1 else "")
        print("| %s | %s | %d | %s | %s | %.3g %% | %s |" % (
            est, verdict, t.n, pct(t.cov1, t.n), pct(t.cov0, t.judged0),
            100 * statistics.median(t.width) if t.width else float("nan"), worst))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="estimators: " + ", ".join(candidates.ESTIMATORS))
    ap.add_argument("gridfree")
    ap.add_argument("--estimators", default="averaged,averaged+order,capped,fm,eh14")
    ap.add_argument("--source", action="append", help="only this corpus file (stem); repeatable")
    ap.add_argument("--windows", action="store_true", help="name the worst window of each row")
    ap.add_argument("--series", action="store_true", help="also judge each whole series (all its grids)")
    ap.add_argument("--misses", metavar="VERDICT", help="list every window of this verdict whose f₁ ± U₁ missed")
    args = ap.parse_args()
    ests = args.estimators.split(",")
    for e in ests:
        if e not in candidates.ESTIMATORS:
            sys.exit("unknown estimator %s; valid: %s" % (e, ", ".join(candidates.ESTIMATORS)))
    runner = candidates.Runner(args.gridfree)
    overall, whole = {}, {}
    for stem, doc in load_corpus(args.source):
        per = {}
        nwin = 0
        for s in doc["series"]:
            ref, order = s["reference"], s.get("formal_order")
            for h, f in windows(s):
                nwin += 1
                label = "%s, h %.3g–%.3g" % (s["name"], h[0], h[-1])
                for e in ests:
                    w = candidates.ESTIMATORS[e](runner, h, f, order)
                    if w is None or w.get("u1") is None:
                        continue
                    if args.misses == w["verdict"] and abs(ref - w["f1"]) > w["u1"]:
                        print("miss: %s %s: %s; f1 %.6g ± %.3g, f0 %.6g, p %s, reference %.6g (%.2f U₁)" % (
                            e, stem, label, w["f1"], w["u1"], w["f0"], w.get("p"), ref,
                            abs(ref - w["f1"]) / w["u1"]), file=sys.stderr)
                    for key in ((e, w["verdict"]), (e, "all")):
                        per.setdefault(key, Tally()).add(w, ref, label)
                        overall.setdefault(key, Tally()).add(w, ref, stem + ": " + label)
            if args.series and len(s["h"]) >= 4:
                for e in ests:
                    w = candidates.ESTIMATORS[e](runner, s["h"], s["f"], order)
                    if w is None or w.get("u1") is None:
                        continue
                    whole.setdefault((e, w["verdict"]), Tally()).add(w, ref, stem + ": " + s["name"])
        table("%s: %s (%d series, %d windows)" % (stem, doc["source"], len(doc["series"]), nwin), per,
              args.windows)
    table("all sources", overall, args.windows)
    if args.series:
        table("whole series (all grids)", whole, True)


if __name__ == "__main__":
    main()
