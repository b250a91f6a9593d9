#!/usr/bin/env python3
"""The documentation's structure (no liggghts needed): README's "Read on" links every page of doc/
(a guide, a results page or a command page), and doc/design.md's sections stand in the order of
their numbers.

  python3 test_docs.py LIGGGHTS WORKDIR CASE"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_run import check  # noqa: E402
from liggghts_run import main as test_main  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def case_readme_links_every_page(liggghts, work):
    """Every doc/*.md and doc/*.txt is linked from README.md's "Read on" (a page linked from nowhere
    is a page no user finds), and every page it links exists."""
    del liggghts, work
    text = open(os.path.join(ROOT, "README.md")).read()
    read_on = text[text.index("## Read on"):]
    linked = set(re.findall(r"\((doc/[^)#]+)", read_on))
    pages = set(os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "doc", "*.md")) +
                glob.glob(os.path.join(ROOT, "doc", "*.txt")))
    check(not pages - linked, "README's Read on links every page of doc/ (missing: %s)" % sorted(pages - linked))
    check(not linked - pages, "every page it links exists (missing: %s)" % sorted(linked - pages))


def case_design_sections_in_order(liggghts, work):
    """doc/design.md's sections are numbered in the order they stand (4, 4a, 4b, ... then 5)."""
    del liggghts, work
    numbers = re.findall(r"^## (\d+)([a-z]?)\. ", open(os.path.join(ROOT, "doc", "design.md")).read(), re.M)
    keys = [(int(n), letter) for n, letter in numbers]
    check(keys == sorted(keys) and len(set(keys)) == len(keys), "design.md's sections in order: %s"
          % ", ".join("%d%s" % k for k in keys))


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
