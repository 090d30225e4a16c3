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
#  - every link or image to a relative path names a file that exists (beside FILE.md);
#  - every link with a fragment to a Markdown file ("other.md#a-heading", or "#a-heading"
#    within FILE.md) names a heading there by its GitHub-style anchor: the heading's text
#    lowercased, punctuation dropped but for '-' and '_', spaces turned into '-'; a repeated
#    anchor gets -1, -2, ... in order (see heading_anchors below).
# A "#" heading (level 1) is not required: shell comments in code blocks start that way.
# Usage: tools/check-markdown.sh FILE.md...   (exit 0: all render right; 1: one line per problem)
set -euo pipefail
# Plain POSIX awk (Debian's default is mawk): no {m,n} intervals in the patterns.

[ $# -gt 0 ] || { echo "usage: check-markdown.sh FILE.md..."; exit 1; }
command -v cmark > /dev/null || { echo "check-markdown: cmark not found (tools/install-deps.sh installs it)"; exit 1; }

# The anchors GitHub gives FILE's headings, one a line, in order (github-slugger's rules): the
# heading's rendered text (cmark's HTML, tags and entities dropped), lowercased (ASCII),
# ASCII punctuation other than '-' and '_' dropped, and the common non-ASCII punctuation and
# symbols too (letters and digits of any script stay), each space turned into '-'; an anchor
# seen before gets -1, -2, ... (the first suffix that is free).
heading_anchors() {
    cmark --to html "$1" |
        sed -n 's/^<h[1-6][^>]*>\(.*\)<\/h[1-6]>$/\1/p' |
        sed 's/<[^>]*>//g; s/&[A-Za-z][A-Za-z]*;//g; s/&#[0-9][0-9]*;//g; s/&#[xX][0-9A-Fa-f][0-9A-Fa-f]*;//g' |
        LC_ALL=C sed 's/[][!"#$%&'"'"'()*+,./:;<=>?@\\^`{|}~]//g' |
        sed 's/—//g; s/–//g; s/‘//g; s/’//g; s/“//g; s/”//g; s/…//g; s/×//g; s/·//g; s/→//g; s/≤//g; s/≥//g; s/±//g; s/°//g; s/²//g' |
        LC_ALL=C tr 'A-Z ' 'a-z-' |
        awk '{
            slug = $0; base = slug
            while (slug in seen) { seen[base]++; slug = base "-" seen[base] }
            seen[slug] = 0
            print slug
        }'
}

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
    local target path fragment
    while IFS= read -r target; do
        case $target in *://*|mailto:*) continue ;; esac
        path=${target%%#*}
        if [ -n "$path" ]; then
            [ -e "$(dirname "$file")/$path" ] || { echo "$file: link to \"$path\", which does not exist"; problems=1; continue; }
        fi
        case $target in *'#'*) fragment=${target#*#} ;; *) continue ;; esac
        # Fragments are checked in Markdown files only (a source file's #L12 is GitHub's).
        if [ -z "$path" ]; then path=$file; else path=$(dirname "$file")/$path; fi
        case $path in *.md) ;; *) continue ;; esac
        [ -f "$path" ] || continue
        [ -n "${anchors_of[$path]+set}" ] || anchors_of[$path]=$(heading_anchors "$path")
        grep -qxF -- "$fragment" <<< "${anchors_of[$path]}" ||
            { echo "$file: link to \"$target\": $path has no heading with the anchor \"#$fragment\""; problems=1; }
    done < <(cmark --to xml "$file" | grep -o '<\(link\|image\) destination="[^"]*"' | sed 's/.*destination="//; s/"$//')
    return $problems
}

declare -A anchors_of  # each linked file's anchors, worked out once
status=0
for file in "$@"; do check_file "$file" || status=1; done
exit $status
