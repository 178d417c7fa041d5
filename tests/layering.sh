#!/bin/sh
# The layers of the tree (docs/architecture.md). Each #include "..." is resolved as the
# compiler finds it (the including file's folder, then the include roots of the build) to
# the folder it lives in, and checked against what that folder may use:
#   core/       its folders are layers: numerics, model, search, aspects (io stands apart
#               and includes none of them); a file includes only its own layer and those
#               before it, so the model language knows nothing of the search, nor the
#               search of Section 4. Nothing outside core/.
#   proofs/     core/ only.
#   certificates/ (the writer) core/ and proofs/; certificates/checker/ itself: nothing
#               but its own files (the independent checker shares no code).
#   results/    core/, proofs/, the writer: never the run (a result is read the same
#               whoever wrote it) nor the distribution or planning.
#   run/        results/ and below; not the distribution (which uses the run through
#               SharedSearch) nor planning.
#   distribution/  run/ and below.
#   planning/   results/ and below.
#   apps/, python/src/  the front ends: any library, never each other.
# No library includes apps/ or python/.
# Usage: layering.sh ROOT (the source tree). Prints each offending include; exit 1 if one.
root=${1:?usage: layering.sh ROOT}
status=0

# The folder (core/model, proofs, results, ...) that the include NAME of FILE resolves to;
# empty when it is none of the project's (a generated or system header).
owner() {  # owner FILE NAME
  for d in "$(dirname "$1")" "$root/core" "$root/proofs" "$root/certificates" \
           "$root/planning" "$root/apps" "$root/python/src" "$root"; do
    if [ -f "$d/$2" ]; then
      p=$(cd "$(dirname "$d/$2")" && pwd)
      p=${p#"$root"/}
      case $p in
        core/*|certificates/checker*|python/src*) echo "$p" ;;
        *) echo "${p%%/*}" ;;
      esac
      return
    fi
  done
}

# check FOLDER ALLOWED...: every include of FOLDER's files resolves into FOLDER or ALLOWED
# (a folder name, or a core/ layer such as core/model).
check() {
  folder=$1; shift
  for f in $(find "$root/$folder" -maxdepth 1 \( -name '*.h' -o -name '*.cpp' \) | sort) \
           $(find "$root/$folder" -mindepth 2 \( -name '*.h' -o -name '*.cpp' \) \
             ! -path '*/tests/*' ! -path "$root/certificates/checker/*" | sort); do
    for inc in $(sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f"); do
      o=$(owner "$f" "$inc")
      [ -z "$o" ] && continue
      ok=0
      for a in "$folder" "$@"; do
        case $o in "$a"|"$a"/*) ok=1 ;; esac
      done
      if [ $ok = 0 ]; then
        echo "layering: ${f#"$root"/} includes $inc ($o/), which $folder/ may not use"
        status=1
      fi
    done
  done
}

# core/'s layers, each with its own folder only (so that check does not take the subfolders
# of core/ for core/ itself).
check_core() {  # check_core LAYER ALLOWED...
  layer=$1; shift
  for f in "$root/core/$layer"/*.h "$root/core/$layer"/*.cpp; do
    [ -f "$f" ] || continue
    for inc in $(sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f"); do
      o=$(owner "$f" "$inc")
      [ -z "$o" ] && continue
      ok=0
      for a in "core/$layer" "$@"; do [ "$o" = "$a" ] && ok=1; done
      if [ $ok = 0 ]; then
        echo "layering: ${f#"$root"/} includes $inc ($o/), above its layer core/$layer/"
        status=1
      fi
    done
  done
}

check_core numerics
check_core model core/numerics
check_core search core/numerics core/model
check_core aspects core/numerics core/model core/search
check_core io
check proofs core
check certificates core proofs
check certificates/checker
check results core proofs certificates
check run core proofs certificates results
check distribution core proofs certificates results run
check planning core proofs certificates results
check apps core proofs certificates results run distribution planning
check python/src core proofs certificates results run planning
exit $status
