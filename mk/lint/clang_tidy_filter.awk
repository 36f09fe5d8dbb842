# clang_tidy_filter.awk — reduces clang-tidy's raw per-file logs to the findings that are
# not suppressed (docs/lint.md).
#   awk -v root=/abs/tree -f clang_tidy_filter.awk SUPPRESSIONS RAW_LOG...
# SUPPRESSIONS: "<check> <path-glob>" per line ('*' stays inside one path component),
# '#' starts a comment.  A finding is "<path>:<line>:<col>: warning|error: <text> [<checks>]",
# its text possibly continued on the next lines; each is printed once (a header's finding
# comes from every file that includes it).  An entry that matches nothing is stale and is
# reported too, so the file keeps only what is still needed.  Exit status 1 if anything printed.

function glob_re(glob,    re) {
	re = glob
	gsub(/[.+?()|{}^$]/, "\\\\&", re)
	gsub(/\*/, "[^/]*", re)
	return "^" re "$"
}

# path relative to the tree, with "dir/../" folded away
function tidy_path(path,    prev) {
	if (index(path, root "/") == 1)
		path = substr(path, length(root) + 2)
	do {
		prev = path
		sub(/[^\/]+\/\.\.\//, "", path)
	} while (path != prev)
	return path
}

function report(finding,    loc, path, checks, n, names, i, j, hit) {
	if (!match(finding, /\[[A-Za-z0-9.,_-]+\]$/))
		return
	checks = substr(finding, RSTART + 1, RLENGTH - 2)
	loc = finding
	sub(/:.*/, "", loc)
	path = tidy_path(loc)
	finding = path substr(finding, length(loc) + 1)
	n = split(checks, names, ",")
	for (i = 1; i <= n; i++)
		for (j = 1; j <= nsupp; j++)
			if (names[i] ~ supp_check[j] && path ~ supp_path[j]) {
				used[j] = 1
				hit = 1
			}
	if (!hit && !(finding in seen)) {
		seen[finding] = 1
		print finding
		found++
	}
}

FNR == 1 { nfile++ }

nfile == 1 {
	sub(/#.*/, "")
	if (NF == 0)
		next
	if (NF != 2) {
		printf "%s:%d: expected \"<check> <path-glob>\"\n", FILENAME, FNR
		found++
		next
	}
	nsupp++
	supp_check[nsupp] = glob_re($1)
	supp_path[nsupp] = glob_re($2)
	supp_text[nsupp] = FILENAME ":" FNR ": " $1 " " $2
	next
}

# a finding starts; one whose text runs on is joined until its [check] arrives
/^[^ :]+:[0-9]+:[0-9]+: (warning|error): / {
	if (pending != "")
		report(pending)
	pending = $0
	if (pending ~ /\]$/) {
		report(pending)
		pending = ""
	}
	next
}

pending != "" {
	pending = pending " " $0
	if ($0 ~ /\[[A-Za-z0-9.,_-]+\]$/) {
		report(pending)
		pending = ""
	}
}

END {
	if (pending != "")
		report(pending)
	for (j = 1; j <= nsupp; j++)
		if (!used[j]) {
			print supp_text[j] ": stale suppression (matches no finding): remove it"
			found++
		}
	exit found ? 1 : 0
}
