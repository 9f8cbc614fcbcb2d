"""Checks that every relative link of README.md and docs/src/ (Markdown links
and images) points to a file or folder of the repository. External links
(http:, https:, mailto:) are not fetched: CI has no network to them.

    python3 scripts/check-links.py    # from anywhere; exit 1 and one line per broken link

Written by hand: the link checkers of the mdBook ecosystem (mdbook-linkcheck)
add a long build to CI for what is a few lines here.
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
# [text](target) and ![alt](target); a target ends at the first space or ')'.
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def links(path):
    """(line number, target) of every link outside code blocks and inline code."""
    inside = False
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if FENCE.match(line):
            inside = not inside
            continue
        if inside:
            continue
        for target in LINK.findall(re.sub(r"`[^`]*`", "", line)):
            yield number, target


def main():
    files = [ROOT / "README.md", *sorted((ROOT / "docs" / "src").rglob("*.md"))]
    broken, checked = [], 0
    for path in files:
        for number, target in links(path):
            if re.match(r"^[a-z][a-z0-9+.-]*:", target) or target.startswith("#"):
                continue
            checked += 1
            resolved = (path.parent / target.split("#", 1)[0]).resolve()
            if not resolved.exists() or ROOT not in [resolved, *resolved.parents]:
                broken.append(f"{path.relative_to(ROOT)}:{number}: {target} does not resolve")
    for line in broken:
        print(line)
    print(f"{checked} relative links in {len(files)} files, {len(broken)} broken", file=sys.stderr)
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
