# bash completion for dartcheck (installed by `cmake --install` as
# share/bash-completion/completions/dartcheck). Commands, options and the
# values of options with a fixed set of choices ("--format TEXT:{text,json}")
# are read from dartcheck's own --help, so they cannot go stale; the names
# of --rule and --map come from the catalog on the command line, and those
# of --map, --model and --cells from the binary (`dartcheck __complete`);
# any other word completes as a file name.
_dartcheck() {
  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]} program=${COMP_WORDS[0]}
  local top commands cmd="" w help
  top=$("$program" --help 2>/dev/null) || return
  commands=$(printf '%s\n' "$top" | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}')
  # The command is the first word that names one (a global option's value,
  # as in `--limit-darts 5 check`, does not).
  for w in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
    if printf '%s\n' "$commands" | grep -qx -- "$w"; then
      cmd=$w
      break
    fi
  done
  help=$top
  [ -n "$cmd" ] && help+=$'\n'$("$program" "$cmd" --help 2>/dev/null)
  if [[ $prev == --rule || $prev == --map || $prev == --model || $prev == --cells ]]; then
    # The catalog: --catalog's value, else the first .yaml/.yml/.jme word.
    local catalog="" i words=("${COMP_WORDS[@]:1:COMP_CWORD-1}")
    for ((i = 0; i < ${#words[@]}; i++)); do
      if [ "${words[i]}" = --catalog ]; then
        catalog=${words[i + 1]}
        break
      fi
      case ${words[i]} in *.yaml | *.yml | *.jme) [ -z "$catalog" ] && catalog=${words[i]} ;; esac
    done
    local what
    case $prev in --rule) what=rules ;; --map) what=maps ;; --model) what=models ;; --cells) what=cells ;; esac
    local names
    names=$("$program" __complete "$what" ${catalog:+"$catalog"} 2>/dev/null)
    local IFS=$'\n'
    mapfile -t COMPREPLY < <(compgen -W "$names" -- "$cur")
    # --map also takes a map file.
    [ "$prev" = --map ] && mapfile -t -O "${#COMPREPLY[@]}" COMPREPLY < <(compgen -f -- "$cur")
    return
  fi
  if [[ $prev == --* ]]; then
    local choices
    choices=$(printf '%s\n' "$help" | sed -n "s/^ *\(-[a-zA-Z],\)\{0,1\}$prev [A-Z]*:{\([^}]*\)}.*/\2/p" | head -n 1)
    if [ -n "$choices" ]; then
      mapfile -t COMPREPLY < <(compgen -W "${choices//,/ }" -- "$cur")
      return
    fi
  fi
  if [[ $cur == -* ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$(printf '%s\n' "$help" | grep -o -- '--[a-z][a-z-]*' | sort -u)" -- "$cur")
  elif [ -z "$cmd" ]; then
    mapfile -t COMPREPLY < <(compgen -W "$commands help" -- "$cur")
  else
    mapfile -t COMPREPLY < <(compgen -f -- "$cur")
  fi
}
complete -o filenames -F _dartcheck dartcheck
