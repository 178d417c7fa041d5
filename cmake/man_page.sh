#!/bin/sh
# Usage: man_page.sh HELP2MAN PROGRAM OUT DESCRIPTION
# Writes OUT, the man page of PROGRAM made by help2man from its --help and --version. A
# program with subcommands (the "Subcommands:" list of its --help, as aspects has) gets a
# section SUBCOMMANDS holding each one's --help, so that the page says every option.
# Written to a temporary name and renamed when complete.
set -e
help2man=$1
program=$2
out=$3
description=$4
name=$(basename "$program")
tmp=$out.tmp.$$
trap 'rm -f "$tmp" "$tmp.include"' EXIT HUP INT TERM

# roff: backslashes doubled, dashes as \-, a line starting with . or ' kept as text.
to_roff() {
  sed -e 's/\\/\\\\/g' -e 's/-/\\-/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
}

subcommands=$("$program" --help | sed -n '/^Subcommands:/,$p' | sed -n 's/^  \([a-z][a-z_-]*\)  .*/\1/p')
: > "$tmp.include"
if [ -n "$subcommands" ]; then
  echo "[SUBCOMMANDS]" >> "$tmp.include"
  for sub in $subcommands; do
    printf '.SS "%s %s"\n.nf\n' "$name" "$sub" >> "$tmp.include"
    "$program" "$sub" --help | to_roff >> "$tmp.include"
    printf '.fi\n' >> "$tmp.include"
  done
fi
printf '[SEE ALSO]\n%s\n' "$( [ "$name" = aspects ] && echo 'check_cert(1)' || echo 'aspects(1)'); certificates/FORMAT.md and README.md of the source" >> "$tmp.include"

"$help2man" --no-info --name "$description" --include "$tmp.include" --output "$tmp" "$program"
mv "$tmp" "$out"
