#!/usr/bin/env bash
# Checks that a Markdown file renders as its author meant under CommonMark (cmark, the
# reference implementation, from Debian's cmark package):
#  - every line that starts with "## " .. "###### " is rendered as a heading: a stray or
#    unclosed code fence swallows the headings after it into a code block;
#  - every fenced code block ends on a line that is only a fence: a fence followed by text
#    ("``` text") does not close a block, so the block runs on to the next bare fence (or to
#    the end of the file) and every fence after it pairs up wrongly;
#  - no fenced code block holds a line that starts like a fence of its own kind (the
#    "``` text" that the author meant as a closing fence);
#  - every link or image to a relative path names a file that exists (beside FILE.md).
# A "#" heading (level 1) is not required: shell comments in code blocks start that way.
# Usage: tools/check-markdown.sh FILE.md...   (exit 0: all render right; 1: one line per problem)
set -euo pipefail
# Plain POSIX awk (Debian's default is mawk): no {m,n} intervals in the patterns.

[ $# -gt 0 ] || { echo "usage: check-markdown.sh FILE.md..."; exit 1; }
command -v cmark > /dev/null || { echo "check-markdown: cmark not found (tools/install-deps.sh installs it)"; exit 1; }

# Prints one line per problem of one file; fails when there is any.
check_file() {
    local file=$1 rendered problems=0
    [ -r "$file" ] || { echo "$file: cannot read"; return 1; }
    # Rendered node start/end lines, from cmark's XML with source positions:
    #   heading START   and   code_block START END
    rendered=$(cmark --to xml --sourcepos "$file" |
        sed -n -E 's/^ *<(heading|code_block) sourcepos="([0-9]+):[0-9]+-([0-9]+):[0-9]+".*/\1 \2 \3/p')
    awk -v file="$file" -v rendered="$rendered" '
    BEGIN {
        n = split(rendered, lines, "\n")
        for (i = 1; i <= n; ++i) {
            split(lines[i], f, " ")
            if (f[1] == "heading") heading[f[2]] = 1
            else if (f[1] == "code_block") { blockStart[++blocks] = f[2]; blockEnd[blocks] = f[3] }
        }
    }
    { source[NR] = $0 }
    END {
        problems = 0
        for (i = 1; i <= NR; ++i)
            if (source[i] ~ /^(   |  | )?###?#?#?#?( |$)/ && !(i in heading)) {
                printf "%s:%d: \"%s\" is not rendered as a heading (inside a code block?)\n", file, i, source[i]
                ++problems
            }
        for (b = 1; b <= blocks; ++b) {
            first = blockStart[b]; last = blockEnd[b]
            if (!match(source[first], /^(   |  | )?(````*|~~~~*)/)) continue  # indented block
            fence = substr(source[first], RSTART, RLENGTH); sub(/^ +/, "", fence)
            kind = substr(fence, 1, 1)  # a block closes only on a fence of its own character
            if (last == first || source[last] !~ ("^(   |  | )?" kind kind kind kind "*[ \t]*$")) {
                printf "%s:%d: code fence opened here is never closed (it runs to line %d)\n", file, first, last
                ++problems
            }
            for (i = first + 1; i < last; ++i)
                if (source[i] ~ ("^(   |  | )?" kind kind kind)) {
                    printf "%s:%d: \"%s\" is inside the code block opened at line %d: a closing fence takes no text after it\n", file, i, source[i], first
                    ++problems
                }
        }
        exit problems > 0
    }' "$file" || problems=1
    # Links and images: what cmark parsed as such, so code blocks and spans do not count.
    local target
    while IFS= read -r target; do
        case $target in *://*|mailto:*|\#*) continue ;; esac
        target=${target%%#*}
        [ -e "$(dirname "$file")/$target" ] || { echo "$file: link to \"$target\", which does not exist"; problems=1; }
    done < <(cmark --to xml "$file" | grep -o '<\(link\|image\) destination="[^"]*"' | sed 's/.*destination="//; s/"$//')
    return $problems
}

status=0
for file in "$@"; do check_file "$file" || status=1; done
exit $status
