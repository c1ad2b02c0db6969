# Completes one command line in a real interactive zsh with zsh's own
# completion system, and prints what it offered, one match a line.
# Usage: zsh -f zsh_complete.zsh FOLDER 'robotsim ch'
# FOLDER holds _robotsim; it goes first on $fpath and compinit finds it by
# its #compdef line, as an installed vendor-completions folder would be.
# zsh offers matches only to its line editor, which runs only with a
# terminal: zsh/zpty gives the inner zsh one. In the inner shell, compadd
# (through which every completion function offers its matches) is wrapped
# to print each match between markers instead of adding it, and a
# completion post-function prints an end marker and leaves; the outer
# script types the line and a Tab, then reads up to the end marker. (The
# markers are written split in two, "<<do""ne>>", so that the terminal's
# echo of the definitions is not taken for them.)
zmodload zsh/zpty || exit 3
folder=$1 line=$2
zpty inner 'zsh -f -i'
zpty -w inner "PS1='' PROMPT_EOL_MARK=''; fpath=(${(q)folder} \$fpath); autoload -Uz compinit; compinit -u -D"
zpty -w inner 'compadd() {
  if (( ${@[(I)-[OAD]*]} )); then builtin compadd "$@"; return; fi
  local -a __hits; builtin compadd -A __hits "$@"
  local hit; for hit in $__hits; do print -r -- "<<h""it:$hit>>"; done
}'
zpty -w inner '__robotsim_test_done() { print -r -- "<<do""ne>>"; exit 0 }; comppostfuncs=(__robotsim_test_done)'
zpty -w -n inner "$line"$'\t'
output=''
while zpty -r inner chunk; do
  output+=$chunk
  [[ $output == *'<<done>>'* ]] && break
done
zpty -d inner
[[ $output == *'<<done>>'* ]] || { print -u2 "zsh_complete: no end marker; zsh said: $output"; exit 4 }
# A hit may share its line with the line editor's output: take each marker.
print -r -- ${output//$'\r'/} | grep -ao '<<hit:[^<>]*>>' | sed -e 's/^<<hit://' -e 's/>>$//' | sort -u
