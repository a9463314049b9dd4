#!/usr/bin/python3
"""doc_links: every relative link in the docs names a file that exists.

Files move (issue 24 moved most of them); a guide whose links lead nowhere sends a newcomer to
nothing. This reads every tracked Markdown file and checks each relative link `[text](path)` or
`[text](path#anchor)` against the tree (anchors themselves are not checked; web links are left
alone). Before the docs, the checker must flag a made-up broken link, so a checker that accepts
everything fails here.

Usage: doc_links.py --source DIR
"""

import argparse
import os
import re
import subprocess
import sys

LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")


def broken_links(source, markdown_files, read):
    found = []
    for md in markdown_files:
        base = os.path.dirname(md)
        for number, line in enumerate(read(md).splitlines(), 1):
            for match in LINK.finditer(line):
                target = match.group(1)
                if re.match(r"^[a-z]+:", target):
                    continue  # https:, mailto:
                if not os.path.exists(os.path.normpath(os.path.join(source, base, target))):
                    found.append(f"{md}:{number}: link to {target}, which does not exist")
    return found


def self_test(source):
    texts = {"docs/a.md": "[ok](../README.md) [web](https://example.org) [gone](../no/such/file.cc#L3)\n"}
    found = broken_links(source, list(texts), texts.__getitem__)
    if len(found) != 1 or "no/such/file.cc" not in found[0]:
        raise SystemExit(f"FAIL: self test: expected exactly the broken link flagged, got {found}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the repository's root")
    args = parser.parse_args()
    self_test(args.source)
    listed = subprocess.run(["git", "-C", args.source, "ls-files", "*.md"], stdout=subprocess.PIPE, text=True, check=True)
    markdown = [f for f in listed.stdout.splitlines() if os.path.isfile(os.path.join(args.source, f))]

    def read(path):
        with open(os.path.join(args.source, path), encoding="utf-8", errors="replace") as f:
            return f.read()

    found = broken_links(args.source, markdown, read)
    for line in found:
        print(line)
    if found:
        print(f"FAIL: {len(found)} link(s) to files that do not exist")
        return 1
    print(f"PASS: every relative link of {len(markdown)} Markdown files leads to a file")
    return 0


if __name__ == "__main__":
    sys.exit(main())
