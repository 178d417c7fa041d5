#!/usr/bin/python3
"""Issue 30's scaling study: replays the distributed search's scheduler on the measured cost
of each subtree (`aspects solve --subtree-stats FILE --cut-depth D`) for P simulated ranks of
T threads, and prints the predicted speed-up, efficiency and load balance as a markdown
table; with --plot, a PNG.

What is replayed (distribution/mpi_subtrees.cpp, proofs/pipeline/search_phase.cpp):
  - rank 0 searches the top of the tree alone, cut at depth d = max(8, ceil(log2(256 P T)))
    (--per-thread N for another count a thread, --old-cut for the first slice's 8 a rank,
    --deeper K levels more); its time is the measured top's (recorded at a finer cut D)
    times the share of the top's boxes above depth d (the CSV's level rows);
  - a subtree of the cut at d is the group of recorded subtrees under it: its work is the
    sum of their thread CPU seconds, plus the top's boxes between d and D at the top's cost
    per box, shared among the groups by their number of recorded subtrees (a group's own
    count of them is not recorded);
  - then every thread of every rank takes the next subtree when it is idle, depth first
    (--order heaviest: first the subtrees of the runs that have taken longest so far; tried
    in the replay, not built);
  - a thread of another rank encodes its part (as long as rank 0's decoding, measured) and
    sends it with its certificate records (--records-per-node bytes each: a part's records
    are not known when rank 0 searched it). With --async-parts (as built since the fourth
    slice) it asks for its next subtree at once (a request and its answer: 2 × --latency)
    while its part queues at rank 0; without, it waits until rank 0 has taken the part in.
    Rank 0's serving thread takes one part at a time: it receives it at --bandwidth bytes/s,
    decodes it (measured; with --decode-at-merge, as built, it keeps the bytes and the merge
    decodes each part as it grafts it, added to the later phases) and writes its records
    to a file at --disk bytes/s (CertificateWriter::restore; with --records-at-end, as built
    without checkpoints since the fifth slice, the records stay with the rank that searched
    and rank 0 fetches them as it writes the certificate: their transfer at --bandwidth is
    added to the later phases instead); each message waits --latency
    seconds on top (the ranks poll, sleeping up to 1 ms). --free-ingest makes all of this
    free: what the scheduler alone would give. The search ends when the last part is in;
  - rank 0 then runs every later phase alone: the measured `phase_seconds` of the run
    (summary.json) but the search's, at the run's thread count (they use rank 0's threads).

The speed-up of P ranks is against one rank of the same T threads, replayed the same way
(its cut: depth 8). Efficiency = speed-up / P. Load balance: the busiest rank's search
seconds over the mean (1 is perfect). The whole run cannot scale beyond
(search + later phases) / later phases (Amdahl): the table says so.

--grow-from CSV: a coarser run of the same model at the same cut (say eps 0.6 beside 0.3):
each subtree of the last --stats is extrapolated to a finer eps by the growth of the boxes
of its group (the recorded subtrees under its path of length --grow-depth; default the
recorded depth, each subtree alone) between the two,
g = (n / n_coarse) ** (log(eps / eps_target) / log(eps_coarse / eps)), its seconds, boxes
and bytes multiplied by g; then all rescaled so that the boxes sum to --target-nodes when
given (a measured total), at the cost per box measured at eps. An extrapolation, not a
measurement: checked against a measured pair in bench/RESULTS.md ("Issue 30, fourth slice"),
where groups at depth 0 to 12 predict the replay of the measured eps within 2 points and
each subtree alone (depth 16) does not (a subtree of one node at the coarser eps grows
without meaning).

Usage: scaling_replay.py --stats CSV --summary JSON [--label TEXT] [--threads T]
  [--ranks 1,2,4,...] [--plot PNG] [--latency S] [--bandwidth B] [--disk B]
  [--records-per-node B] [--per-thread N | --old-cut] [--deeper K] [--no-cert]
  [--free-ingest] [--async-parts] [--decode-at-merge] [--records-at-end] [--part-scale F]
  [--order dfs|heaviest [--blocks B]]
  [--grow-from CSV --eps E --eps-coarse E --eps-target E [--grow-depth G]
  [--target-nodes N] [--later-seconds S] [--extra-records-per-node B]]
"""
import argparse
import csv
import gzip
import heapq
import json
import math
import sys


def read_rows(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt") as f:
        rows = list(csv.DictReader(f))
    top = [r for r in rows if r["part"] == "top"]
    levels = [int(r["nodes"]) for r in rows if r["part"] == "level"]
    sub = [r for r in rows if r["part"] == "subtree"]
    if len(top) != 1 or not sub or any(r["nodes"] == "" or r["cpu_seconds"] == "" for r in sub):
        sys.exit(f"{path}: needs one top row and every subtree searched by this process")
    if len(levels) != int(sub[0]["depth"]) or sum(levels) != int(top[0]["nodes"]):
        sys.exit(f"{path}: needs one level row per depth above the cut")
    return top[0], levels, sub


def cut_for(ranks, threads, a):
    """distribution/mpi_subtrees.cpp's defer_depth_for: --per-thread subtrees a thread of the job
    (256; --old-cut: 8 a rank, the first slice's rule), --deeper levels more."""
    subtrees = 8 * max(1, ranks) if a.old_cut else a.per_thread * max(1, ranks) * max(1, threads)
    return max(8, math.ceil(math.log2(subtrees))) + a.deeper


class Work:
    """The recorded subtrees of one run: path, CPU seconds, nodes, part bytes, decode s."""

    def __init__(self, top, levels, sub, cpu=None):
        self.top_cpu = float(top["cpu_seconds"])
        self.levels = levels
        self.depth = int(sub[0]["depth"])
        self.paths = [r["path"] for r in sub]
        self.cpu = cpu if cpu is not None else [float(r["cpu_seconds"]) for r in sub]
        self.nodes = [int(r["nodes"]) for r in sub]
        self.part_bytes = [int(r["part_bytes"]) for r in sub]
        self.decode = [float(r["decode_seconds"]) for r in sub]
        self.processed = int(top["nodes"]) + sum(self.nodes)

    def coarse(self, depth):
        """The subtrees of a cut at `depth` (<= the recorded one), depth first."""
        if depth > self.depth:
            sys.exit(f"a cut at depth {depth} needs a run recorded at least that deep "
                     f"(recorded: {self.depth})")
        per_box = self.top_cpu / max(1, sum(self.levels))
        between = sum(self.levels[depth:])  # the top's boxes below the cut at `depth`
        groups = {}
        for k, p in enumerate(self.paths):
            g = groups.setdefault(p[:depth], [0.0, 0, 0, 0.0])
            g[0] += self.cpu[k] + per_box * between / len(self.paths)
            g[1] += self.nodes[k]
            g[2] += self.part_bytes[k]
            g[3] += self.decode[k]
        return [groups[p] for p in sorted(groups)]  # sorted paths: depth first

    def top_seconds(self, depth):
        """The top's CPU seconds when cut at `depth`."""
        return self.top_cpu * sum(self.levels[:depth]) / max(1, sum(self.levels))

class DepthFirst:
    """Subtrees in depth-first order (proofs/pipeline/subtree_queue.h)."""

    def __init__(self, n, blocks):
        self.n, self.next = n, 0

    def claim(self, t):
        if self.next >= self.n:
            return None
        self.next += 1
        return self.next - 1

    def finished(self, k, t):
        pass


class HeaviestFirst:
    """Tried, not built: the depth-first order cut into `blocks` runs of
    consecutive subtrees; one subtree from each run in turn until every run has one started,
    then the next subtree of the run whose subtrees have taken longest: the mean of those
    finished, or the longest still running so far, whichever is more."""

    def __init__(self, n, blocks):
        self.b = max(1, min(blocks, n))
        self.start = [n * i // self.b for i in range(self.b + 1)]
        self.cursor = self.start[:-1]
        self.sum = [0.0] * self.b
        self.count = [0] * self.b
        self.running = [dict() for _ in range(self.b)]
        self.explored = 0

    def block(self, k):
        lo, hi = 0, self.b
        while hi - lo > 1:
            mid = (lo + hi) // 2
            if self.start[mid] <= k:
                lo = mid
            else:
                hi = mid
        return lo

    def claim(self, t):
        while self.explored < self.b:
            i = self.explored
            self.explored += 1
            if self.cursor[i] < self.start[i + 1]:
                return self.take(i, t)
        best, best_cost = None, -1.0
        for i in range(self.b):
            if self.cursor[i] >= self.start[i + 1]:
                continue
            cost = self.sum[i] / self.count[i] if self.count[i] else 0.0
            for began in self.running[i].values():
                cost = max(cost, t - began)
            if cost > best_cost:
                best, best_cost = i, cost
        return None if best is None else self.take(best, t)

    def take(self, i, t):
        k = self.cursor[i]
        self.cursor[i] += 1
        self.running[i][k] = t
        return k

    def finished(self, k, t):
        i = self.block(k)
        self.sum[i] += t - self.running[i].pop(k)
        self.count[i] += 1


def replay(work, ranks, threads, a, deeper):
    """Seconds of the search on `ranks` ranks of `threads` threads, and per-rank busy s."""
    depth = min(cut_for(ranks, threads, a) if ranks > 1 else 8 + deeper, work.depth)
    tasks = [(c, n, b * a.part_scale, d * a.part_scale) for c, n, b, d in work.coarse(depth)]
    records_rate = 0 if a.no_cert or a.records_at_end else a.records_per_node
    top = work.top_seconds(depth)
    # Events: (time, order, kind, worker, task). Kinds: 0 ready for a subtree, 1 a part
    # arrives at rank 0's server. A worker w is thread w % threads of rank w // threads.
    events = [(top, w, 0, w, -1) for w in range(ranks * threads)]
    heapq.heapify(events)
    order = len(events)
    server_free, end = top, top
    sched = (HeaviestFirst if a.order == "heaviest" else DepthFirst)(len(tasks), a.blocks)
    current = {}  # worker -> the subtree it searches
    busy = [0.0] * ranks
    while events:
        t, _, kind, w, k = heapq.heappop(events)
        rank = w // threads
        if kind == 1:  # rank 0 takes the part in, then sends the next subtree
            cpu, nodes, part, decode = tasks[k]
            start = max(server_free, t)
            if not a.free_ingest:
                records = nodes * records_rate
                decode_here = 0 if a.decode_at_merge else decode
                server_free = start + (part + records) / a.bandwidth + decode_here + records / a.disk
            else:
                server_free = start
            end = max(end, server_free)
            if not a.async_parts:
                heapq.heappush(events, (server_free + (0 if a.free_ingest else a.latency),
                                        order, 0, w, -1))
                order += 1
            continue
        if kind == 0 and w in current:
            sched.finished(current.pop(w), t)
        k = sched.claim(t)
        if k is None:
            continue
        current[w] = k
        cpu, nodes, part, decode = tasks[k]
        busy[rank] += cpu
        if rank == 0:
            heapq.heappush(events, (t + cpu, order, 0, w, -1))
            end = max(end, t + cpu)
        else:
            sent = t + cpu + (0 if a.free_ingest else decode)  # encoding costs about a decoding
            heapq.heappush(events, (sent + (0 if a.free_ingest else a.latency), order, 1, w, k))
            if a.async_parts:  # asks for its next subtree while its part waits at rank 0
                order += 1
                heapq.heappush(events, (sent + (0 if a.free_ingest else 2 * a.latency), order,
                                        0, w, -1))
        order += 1
    return end, busy, depth, len(tasks)


def later_phases(summary):
    return sum(s for p, s in summary["phase_seconds"].items() if p != "search")


def table(label, work, later, a, out):
    base, _, _, _ = replay(work, 1, a.threads, a, a.deeper)
    records = 0 if a.no_cert else a.records_per_node * sum(work.nodes)
    decode = a.part_scale * sum(work.decode)
    ingest = (a.part_scale * sum(work.part_bytes) / a.bandwidth +
              (0 if a.decode_at_merge else decode))
    if a.records_at_end:  # fetched one subtree at a time as the certificate is written
        later += records / a.bandwidth
    else:
        ingest += records / a.bandwidth + records / a.disk
    if a.decode_at_merge:  # the merge decodes each part as it grafts it, on one thread
        later += decode
    out.append(f"\n{label}: {work.processed:,} boxes processed, {len(work.paths):,} subtrees "
               f"recorded at depth {work.depth}; search work {sum(work.cpu) + work.top_cpu:,.1f} "
               f"CPU s; later phases {later:,.1f} s on rank 0; {a.threads} thread(s) per rank; "
               f"rank 0 takes every part in on one thread: "
               f"{0 if a.free_ingest else ingest:,.1f} s in all"
               f"{' (--free-ingest)' if a.free_ingest else ''}\n")
    out.append("| ranks P | cut | subtrees | per thread | search s | search speed-up | "
               "search eff. | load max/mean | run s | run speed-up | run eff. |")
    out.append("|---|---|---|---|---|---|---|---|---|---|---|")
    points = []
    for p in a.ranks:
        t, busy, depth, n = replay(work, p, a.threads, a, a.deeper)
        balance = max(busy) / (sum(busy) / len(busy)) if sum(busy) > 0 else float("inf")
        s_search = base / t
        s_run = (base + later) / (t + later)
        points.append((p, s_search, s_run, balance))
        out.append(f"| {p:,} | {depth} | {n:,} | {n / (p * a.threads):.1f} | {t:,.2f} | "
                   f"{s_search:,.1f} | {100 * s_search / p:.0f} % | {balance:.2f} | "
                   f"{t + later:,.1f} | {s_run:,.1f} | {100 * s_run / p:.1f} % |")
    out.append(f"\nAmdahl bound of the whole run: {(base + later) / later:,.1f}× "
               f"(the later phases alone, {later:,.1f} s, on rank 0).")
    return points


def extrapolated(work, a):
    """Each subtree grown from eps to eps_target as its boxes grew from eps_coarse to eps."""
    _, _, csub = read_rows(a.grow_from)
    power = math.log(a.eps / a.eps_target) / math.log(a.eps_coarse / a.eps)
    # Growth measured on the groups of subtrees under each path of length --grow-depth (the
    # recorded depth: each subtree alone); every subtree of a group grows alike. A subtree of
    # a few nodes at eps_coarse has no meaningful growth of its own.
    g_depth = a.grow_depth if a.grow_depth is not None else work.depth
    coarse, fine = {}, {}
    for r in csub:
        coarse[r["path"][:g_depth]] = coarse.get(r["path"][:g_depth], 0) + int(r["nodes"])
    for p, n in zip(work.paths, work.nodes):
        fine[p[:g_depth]] = fine.get(p[:g_depth], 0) + n
    growth = []
    for p in work.paths:
        c, n = coarse.get(p[:g_depth], 0), fine[p[:g_depth]]
        # A group the coarser run did not defer or that did not grow: kept as it is.
        growth.append((n / c) ** power if c > 0 and n > c else 1.0)
    if a.target_nodes:  # the shape extrapolated, the size measured
        scale = a.target_nodes / sum(n * g for n, g in zip(work.nodes, growth))
        growth = [g * scale for g in growth]
    w = Work.__new__(Work)
    w.__dict__.update(work.__dict__)
    w.cpu = [x * g for x, g in zip(work.cpu, growth)]
    w.nodes = [int(x * g) for x, g in zip(work.nodes, growth)]
    w.part_bytes = [int(x * g) for x, g in zip(work.part_bytes, growth)]
    w.decode = [x * g for x, g in zip(work.decode, growth)]
    w.processed = sum(w.nodes) + sum(work.levels)
    return w


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--stats", action="append", help="CSV (or .csv.gz)")
    ap.add_argument("--summary", action="append", help="the run's summary.json")
    ap.add_argument("--label", action="append")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--ranks", default="1,2,4,8,16,32,64,128,256,512,1024")
    ap.add_argument("--latency", type=float, default=1e-3, help="seconds a message waits")
    ap.add_argument("--bandwidth", type=float, default=1.25e9, help="bytes/s into rank 0")
    ap.add_argument("--disk", type=float, default=1e9, help="rank 0's disk, bytes/s")
    ap.add_argument("--records-per-node", type=float, default=0,
                    help="certificate record bytes per box processed")
    ap.add_argument("--no-cert", action="store_true", help="no records travel")
    ap.add_argument("--records-at-end", action="store_true",
                    help="records stay with the rank that searched until rank 0 writes the "
                    "certificate (as built without checkpoints since the fifth slice): their "
                    "transfer is added to the later phases, the spool not counted")
    ap.add_argument("--free-ingest", action="store_true",
                    help="rank 0 takes parts in at no cost, no latency: the scheduler alone")
    ap.add_argument("--deeper", type=int, default=0, help="cut this many levels deeper")
    ap.add_argument("--old-cut", action="store_true",
                    help="the first slice's cut: 8 subtrees a rank")
    ap.add_argument("--per-thread", type=int, default=256,
                    help="the cut: this many subtrees a thread of the job (the third slice: 64)")
    ap.add_argument("--async-parts", action="store_true",
                    help="a rank's thread asks for its next subtree as soon as its part is "
                    "sent; rank 0 takes parts in behind (first come, first served)")
    ap.add_argument("--order", choices=["dfs", "heaviest"], default="dfs",
                    help="the order subtrees are handed out in")
    ap.add_argument("--blocks", type=int, default=256, help="--order heaviest's runs")
    ap.add_argument("--decode-at-merge", action="store_true",
                    help="rank 0 keeps parts encoded and decodes each as the merge grafts it "
                    "(added to the later phases)")
    ap.add_argument("--part-scale", type=float, default=1.0,
                    help="parts this many times the recorded bytes and decode seconds")
    ap.add_argument("--scenario", default="", help="appended to every label")
    ap.add_argument("--points-out", help="write the curves as JSON (for --plot-points)")
    ap.add_argument("--plot-points", nargs="+", help="plot these --points-out files only")
    ap.add_argument("--plot")
    ap.add_argument("--grow-from", help="a coarser run's CSV: extrapolate the last --stats")
    ap.add_argument("--grow-depth", type=int,
                    help="--grow-from's growth measured on groups at this depth (default: "
                    "each recorded subtree alone)")
    ap.add_argument("--eps", type=float)
    ap.add_argument("--eps-coarse", type=float)
    ap.add_argument("--eps-target", type=float)
    ap.add_argument("--target-nodes", type=float, help="the boxes the extrapolated search "
                    "processes (measured): all subtrees scaled to it")
    ap.add_argument("--later-seconds", type=float, default=0,
                    help="the later phases' seconds of the extrapolated run (measured)")
    ap.add_argument("--extra-records-per-node", type=float,
                    help="--records-per-node of the extrapolated run")
    a = ap.parse_args()
    a.ranks = [int(x) for x in a.ranks.split(",")]
    if a.plot_points:
        curves = []
        for f in a.plot_points:
            curves += [(c["label"], c["points"]) for c in json.load(open(f))]
        plot(curves, a)
        return
    if not a.stats or len(a.stats) != len(a.summary or []):
        sys.exit("--stats and --summary, one of each per run")
    labels = [x + a.scenario for x in (a.label or a.stats)]
    out, curves = [], []
    for path, summ, label in zip(a.stats, a.summary, labels):
        work = Work(*read_rows(path))
        later = later_phases(json.load(open(summ)))
        curves.append((label, table(label, work, later, a, out)))
    if a.grow_from:
        work = extrapolated(Work(*read_rows(a.stats[-1])), a)
        if a.extra_records_per_node is not None:
            a.records_per_node = a.extra_records_per_node
        label = f"{(a.label or a.stats)[-1]} extrapolated to eps {a.eps_target}{a.scenario}"
        curves.append((label, table(label, work, a.later_seconds, a, out)))
    print("\n".join(out))
    if a.points_out:
        with open(a.points_out, "w") as f:
            json.dump([{"label": l, "points": p} for l, p in curves], f)
    if a.plot:
        plot(curves, a)


def plot(curves, a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 7))
    ranks = a.ranks
    ax1.plot(ranks, ranks, "k:", label="ideal (solid: search, dashed: whole run)")
    for k, (label, pts) in enumerate(curves):
        colour = f"C{k % 10}"
        p = [x[0] for x in pts]
        ax1.plot(p, [x[1] for x in pts], "-o", color=colour, ms=3, label=f"{label}: search")
        ax1.plot(p, [x[2] for x in pts], "--s", color=colour, ms=3)
        ax2.plot(p, [100 * x[1] / x[0] for x in pts], "-o", color=colour, ms=3,
                 label=f"{label}: search")
        ax2.plot(p, [100 * x[2] / x[0] for x in pts], "--s", color=colour, ms=3)
    ax2.axhline(80, color="grey", lw=0.8)
    for ax in (ax1, ax2):
        ax.set_xscale("log", base=2)
        ax.set_xlabel(f"ranks P ({a.threads} thread(s) each)")
        ax.grid(True, which="both", alpha=0.3)
    ax1.set_yscale("log", base=2)
    ax1.set_ylabel("predicted speed-up over one rank")
    ax2.set_ylabel("predicted efficiency (%)")
    ax2.set_ylim(0, 105)
    handles, labels = ax1.get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=2, fontsize=8)
    fig.suptitle("aspects solve under MPI: the scheduler replayed on measured subtree costs "
                 "(issue 30)", fontsize=10)
    fig.tight_layout(rect=(0, 0.04 + 0.022 * ((len(curves) + 2) // 2), 1, 1))
    fig.savefig(a.plot, dpi=110)


if __name__ == "__main__":
    main()
