# Sourced by the scripts that compare two runs' outputs byte for byte (tests/mpi/same_bits.sh,
# tests/mpi/restart_same_n.sh, tools/verify/mpi_all_decks.sh).
#
#   differing_outputs DIR_A DIR_B
#
# Sets DIFFERING to the files of DIR_A's histories and d3plot states that differ in DIR_B
# (space-separated, empty when all are the same), with a note when DIR_B holds another number. d3hsp, the
# lock and the restart dumps are left out, and glstat's "time per zone cycle" line (a timing).
# Sets OUTPUT_FILES to the number of files compared.
differing_outputs() {
  local a=$1 b=$2 f differ=""
  OUTPUT_FILES=0
  for f in $(cd "$a" && ls | grep -v "d3hsp\|lock\|runrsf\|d3dump"); do
    OUTPUT_FILES=$((OUTPUT_FILES + 1))
    if [ "$f" = glstat ]; then
      cmp -s <(grep -v "time per zone" "$a/$f") <(grep -v "time per zone" "$b/$f") ||
        differ="$differ $f"
    else
      cmp -s "$a/$f" "$b/$f" || differ="$differ $f"
    fi
  done
  local other
  other=$(cd "$b" && ls | grep -v "d3hsp\|lock\|runrsf\|d3dump" | wc -l)
  [ "$other" = "$OUTPUT_FILES" ] || differ="$differ (file count $other, not $OUTPUT_FILES)"
  DIFFERING=$differ
}
