#!/bin/sh
# Issue 30's scaling study from the recorded rows in bench/scaling/ (see bench/RESULTS.md,
# "Issue 30, scaling study", for the runs that made them): the tables on stdout, the plot
# in bench/scaling_mpi.png. One rank per core (--threads 1); the later phases are the runs'
# own, measured with 2 threads.
# Usage: sh bench/scaling_study.sh [OUT_PNG]
set -eu
cd "$(dirname "$0")/.."
png=${1:-bench/scaling_mpi.png}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
replay() { /usr/bin/python3 bench/scaling_replay.py --threads 1 "$@"; }
# The first three slices' design (sections up to "Format 3 records"): 8 subtrees a rank
# (--deeper 3: 64), a thread waiting for its part's intake, rank 0 decoding on intake, the
# parts in fixed-width fields (the cut-14 records).
old() { replay --old-cut "$@"; }
rpr() { old --stats bench/scaling/3rpr_eps0.3_cut14.csv.gz \
  --summary bench/scaling/3rpr_eps0.3_summary.json --label "3-RPR eps 0.3" "$@"; }
rrr() { old --stats bench/scaling/3rrr_eps1_cut14.csv.gz \
  --summary bench/scaling/3rrr_eps1_summary.json --label "3-RRR eps 1" "$@"; }
# eps 0.1: each subtree grown as its boxes grew from eps 0.6 to 0.3, scaled to the boxes
# measured at eps 0.1 (232,025,457 processed), with the later phases measured there
# (1,049.8 s: solver 3,315.6 s - search 2,711.8 s + outputs 446.0 s) and 207 record bytes
# per box (48 GB of records); "uniform": every subtree grown alike (the shape of eps 0.3).
e01_shape="--eps 0.3 --eps-coarse 0.6 --eps-target 0.1 --target-nodes 232025457 --later-seconds 1049.8"
e01="$e01_shape --extra-records-per-node 207"
grow_from="--grow-from bench/scaling/3rpr_eps0.6_cut14.csv.gz"
grow="$grow_from $e01"
uniform="--grow-from bench/scaling/3rpr_eps0.3_cut14.csv.gz $e01"
records="--records-per-node 191"  # measured on 3-RPR eps 0.3 (the records' files)

echo "## The first slice, as built: cut at 8 subtrees a rank, certificate records through rank 0"
rpr $records $grow --scenario " (first slice)" --points-out "$work/rpr_asbuilt.json"
rrr $records --scenario " (first slice)" --points-out "$work/rrr_asbuilt.json"
echo "## eps 0.1 grown uniformly, as built"
rpr $records $uniform --scenario " (uniform)" | sed -n '/extrapolated/,$p'
echo "## The scheduler alone (--free-ingest)"
rpr --free-ingest $grow --scenario ", scheduler alone" --points-out "$work/rpr_free.json"
rrr --free-ingest --scenario ", scheduler alone" --points-out "$work/rrr_free.json"
echo "## The scheduler alone, cut 3 levels deeper (64 subtrees a rank)"
rpr --free-ingest --deeper 3 $grow --scenario ", first slice, scheduler alone, cut +3" --points-out "$work/rpr_deeper.json"
rrr --free-ingest --deeper 3 --scenario ", scheduler alone, cut +3" --points-out "$work/rrr_deeper.json"
echo "## eps 0.1 grown uniformly, the scheduler alone, cut +3"
rpr --free-ingest --deeper 3 $uniform --scenario " (uniform), scheduler alone, cut +3" | sed -n '/extrapolated/,$p'
# Format 3 (--cert-format 3): the records a rank sends are binary, the certificate's bytes
# per box processed: 326,929,317 / 21,881,467 = 14.9 at eps 0.3 and 4,381,326,730 /
# 232,703,589 = 18.8 at eps 0.1 (bench/RESULTS.md, "Certificate format 3, built").
grow_v3="--records-per-node 14.9 $grow_from $e01_shape --extra-records-per-node 18.8"
echo "## Format 3 records, as built (cut at 8 subtrees a rank)"
rpr $grow_v3 --scenario " (format 3)"
echo "## Format 3 records, cut +3"
rpr --deeper 3 $grow_v3 --scenario " (format 3), cut +3"
echo "## No certificate (--no-cert: only the parts reach rank 0), cut +3"
rpr --no-cert --deeper 3 $grow --scenario ", no cert, cut +3"

# The fourth slice, as built: 256 subtrees a thread, a thread asks for its next subtree
# while its part travels, rank 0 keeps parts encoded (the compact encoding, measured in the
# cut-16 records) and decodes them at the merge. eps 0.1 extrapolated from eps 0.6 and 0.3
# recorded at cut 16, the growth measured on groups at depth 10 (checked below), or uniform.
now() { replay --async-parts --decode-at-merge "$@"; }
rpr16() { now --stats bench/scaling/3rpr_eps0.3_cut16.csv.gz \
  --summary bench/scaling/3rpr_eps0.3_cut16_summary.json --label "3-RPR eps 0.3" "$@"; }
grow16="--grow-from bench/scaling/3rpr_eps0.6_cut16.csv.gz $e01_shape"
echo "## Fourth slice, as built, format 3 records; eps 0.1 grown by groups at depth 10"
rpr16 --records-per-node 14.9 $grow16 --extra-records-per-node 18.8 --grow-depth 10 \
  --scenario " (fourth slice)" --points-out "$work/rpr_now.json"
echo "## Fourth slice, as built, format 3 records; eps 0.1 grown uniformly"
rpr16 --records-per-node 14.9 $grow16 --extra-records-per-node 18.8 --grow-depth 0 \
  --scenario " (fourth slice, uniform)" | sed -n '/extrapolated/,$p'
echo "## Fourth slice, as built, format 2 records (207 bytes a box at eps 0.1)"
rpr16 --records-per-node 191 $grow16 --extra-records-per-node 207 --grow-depth 10 \
  --scenario " (fourth slice, format 2)" | sed -n '/extrapolated/,$p'
echo "## Fourth slice, the scheduler alone (--free-ingest), groups at depth 10"
rpr16 --free-ingest $grow16 --grow-depth 10 --scenario " (fourth slice), scheduler alone" | sed -n '/extrapolated/,$p'
echo "## Fourth slice's cut against the third's (64 subtrees a thread), scheduler alone"
rpr16 --free-ingest --per-thread 64 $grow16 --grow-depth 10 --scenario " (64 a thread), scheduler alone" | sed -n '/extrapolated/,$p'
echo "## Fourth slice, each subtree grown alone (--grow-depth 16: see the check below)"
rpr16 --records-per-node 14.9 $grow16 --extra-records-per-node 18.8 \
  --scenario " (fourth slice, each subtree grown alone)" | sed -n '/extrapolated/,$p'
echo "## Fourth slice, a 1 Gb/s link into rank 0 instead of 10 Gb/s"
rpr16 --records-per-node 14.9 $grow16 --extra-records-per-node 18.8 --grow-depth 10 \
  --bandwidth 1.25e8 --scenario " (fourth slice, 1 Gb/s)" | sed -n '/extrapolated/,$p'
# The fifth slice: the records stay on the rank that searched until rank 0 writes the
# certificate (without --checkpoint): their transfer is added to the later phases.
echo "## Fifth slice, records held until the certificate is written, format 2 records"
rpr16 --records-at-end --records-per-node 191 $grow16 --extra-records-per-node 207 --grow-depth 10 \
  --scenario " (fifth slice, format 2)" --points-out "$work/rpr_held.json" | sed -n '/extrapolated/,$p'
echo "## Fifth slice, records held until the certificate is written, format 3 records"
rpr16 --records-at-end --records-per-node 14.9 $grow16 --extra-records-per-node 18.8 --grow-depth 10 \
  --scenario " (fifth slice, format 3)" | sed -n '/extrapolated/,$p'
# The check of the extrapolation: eps 0.3 predicted from eps 1.2 and 0.6 (scheduler alone),
# against the replay of the measured eps 0.3 (the first table).
echo "## Check: the measured eps 0.3, scheduler alone"
rpr16 --free-ingest --ranks 16,64,128,256 | grep -v "^$"
for g in 0 8 10 12 16; do
  echo "## Check: eps 0.3 predicted from eps 1.2 and 0.6, groups at depth $g"
  now --stats bench/scaling/3rpr_eps0.6_cut16.csv.gz --summary bench/scaling/3rpr_eps0.6_cut16_summary.json \
    --label "3-RPR eps 0.6" --free-ingest --ranks 16,64,128,256 \
    --grow-from bench/scaling/3rpr_eps1.2_cut16.csv.gz --eps 0.6 --eps-coarse 1.2 --eps-target 0.3 \
    --target-nodes 21846665 --later-seconds 71.6 --grow-depth "$g" | sed -n '/extrapolated/,$p'
done
replay --plot-points "$work"/rpr_asbuilt.json "$work"/rpr_deeper.json "$work"/rrr_asbuilt.json \
  "$work"/rpr_now.json "$work"/rpr_held.json --plot "$png"
echo "plot: $png"
