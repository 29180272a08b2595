"""The docs the package cites are in the repository: every "SPEC §N" in a module names a
section of docs/spec.md, every docs/ page the README links exists, and the README stays a
front page."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def spec_sections():
    text = (ROOT / "docs" / "spec.md").read_text()
    return set(re.findall(r"^#{2,3} (\d+[a-z]?)\.", text, re.M))


def test_every_spec_citation_names_a_section_of_docs_spec():
    sections = spec_sections()
    assert {"1", "2", "2b", "4b", "10"} <= sections
    for path in sorted((ROOT / "wallbsp").rglob("*.py")):
        for cited in re.findall(r"SPEC §(\d+[a-z]?)", path.read_text()):
            assert cited in sections, f"{path.relative_to(ROOT)} cites SPEC §{cited}"


def test_the_readme_links_only_pages_that_exist():
    readme = (ROOT / "README.md").read_text()
    links = re.findall(r"\]\(((?:docs/)[^)#]+)", readme)
    assert links, "the README links its docs"
    missing = [link for link in links if not (ROOT / link).exists()]
    assert not missing, missing


def test_the_readme_is_a_front_page():
    assert len((ROOT / "README.md").read_text().splitlines()) <= 200
