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
    """Every doc/*.md and doc/*.txt, and every study's page, is linked from README.md's "Read on" (a page linked from nowhere
    is a page no user finds), and every page it links exists."""
    del liggghts, work
    text = open(os.path.join(ROOT, "README.md")).read()
    read_on = text[text.index("## Read on"):]
    linked = set(re.findall(r"\(((?:doc|studies)/[^)#]+)", read_on))
    pages = set(os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "doc", "*.md")) +
                glob.glob(os.path.join(ROOT, "doc", "*.txt")) + glob.glob(os.path.join(ROOT, "studies", "*.md")) +
                glob.glob(os.path.join(ROOT, "studies", "*", "README.md")))
    check(not pages - linked, "README's Read on links every page of doc/ (missing: %s)" % sorted(pages - linked))
    check(not linked - pages, "every page it links exists (missing: %s)" % sorted(linked - pages))


def case_design_sections_in_order(liggghts, work):
    """doc/design.md's sections are numbered in the order they stand (4, 4a, 4b, ... then 5)."""
    del liggghts, work
    numbers = re.findall(r"^## (\d+)([a-z]?)\. ", open(os.path.join(ROOT, "doc", "design.md")).read(), re.M)
    keys = [(int(n), letter) for n, letter in numbers]
    check(keys == sorted(keys) and len(set(keys)) == len(keys), "design.md's sections in order: %s"
          % ", ".join("%d%s" % k for k in keys))


def markdown_pages():
    return ([os.path.join(ROOT, "README.md")] + glob.glob(os.path.join(ROOT, "doc", "*.md")) +
            glob.glob(os.path.join(ROOT, "studies", "**", "*.md"), recursive=True) +
            glob.glob(os.path.join(ROOT, "examples", "*", "README.md")))


def case_links_resolve(liggghts, work):
    """Every relative link of every markdown page (README, doc/, studies/, examples/) names a file that
    exists: a moved page or figure leaves no dead link behind."""
    del liggghts, work
    dead = []
    for page in markdown_pages():
        text = re.sub(r"```.*?```", "", open(page).read(), flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            path = target.split("#")[0]
            if not path or re.match(r"[a-z]+:", path):
                continue
            if not os.path.exists(os.path.normpath(os.path.join(os.path.dirname(page), path))):
                dead.append("%s: %s" % (os.path.relpath(page, ROOT), target))
    check(not dead, "every relative link resolves (%d dead: %s)" % (len(dead), "; ".join(dead[:12])))


def case_study_pages(liggghts, work):
    """Each study lives in its own folder of studies/ with its page (README.md), its CSVs and figures
    and its history (history.md); the page is short (under 320 lines) and opens with its conclusions:
    the table 'conclusions', written from the CSVs by post/tables.py, within its first 40 lines."""
    del liggghts, work
    studies = sorted(glob.glob(os.path.join(ROOT, "studies", "*", "README.md")))
    check(len(studies) >= 4, "the studies have folders (%d)" % len(studies))
    for page in studies:
        name = os.path.basename(os.path.dirname(page))
        lines = open(page).read().splitlines()
        check(len(lines) < 320, "%s's page is short: %d lines" % (name, len(lines)))
        opening = [i for i, line in enumerate(lines) if line.startswith("<!-- table conclusions")]
        check(opening and opening[0] < 40, "%s's page opens with its conclusions table (line %s)"
              % (name, opening[0] + 1 if opening else "none"))
        check(os.path.exists(os.path.join(os.path.dirname(page), "history.md")), "%s has its history.md" % name)


if __name__ == "__main__":
    test_main(globals(), sys.argv[1:])
