#!/bin/sh
# The folders of core/ are layers: numerics, model, search, aspects (io stands apart and
# includes none of them). A file includes only its own layer and the layers before it, so
# the model language knows nothing of the search, nor the search of Section 4.
# Usage: layering.sh CORE_DIR. Prints each offending include; exit 1 if there is one.
core=${1:?usage: layering.sh CORE_DIR}
status=0
check() {  # check LAYER ALLOWED...
  layer=$1; shift
  for f in "$core/$layer"/*; do
    for inc in $(sed -n 's/^#include "\([a-z_]*\)\/[a-z_]*\.h"$/\1/p' "$f"); do
      ok=0
      for a in "$layer" "$@"; do [ "$inc" = "$a" ] && ok=1; done
      if [ $ok = 0 ]; then
        echo "layering: $f includes $inc/, above its layer $layer/"
        status=1
      fi
    done
    if grep -q '^#include "[a-z_]*\.h"' "$f"; then
      echo "layering: $f includes a header outside core/"
      status=1
    fi
  done
}
check numerics
check model numerics
check search numerics model
check aspects numerics model search
check io
exit $status
