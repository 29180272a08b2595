"""Reading user files (issue 14 §9): only regular files, or standard input for ``-``, at most
a limit's worth; anything else is one line naming the file, exit 2, nothing written.  A
FIFO is never opened, so nothing here can hang waiting for a writer."""
from __future__ import annotations

import io
import json
import os
import subprocess
import sys

import pytest

from conftest import ROOT
from wallbsp.app.cli import main
from wallbsp.files import InputError, open_regular, read_input
from wallbsp.level.model import LevelError
from wallbsp.level.io import content_hash, load_level

SMALL = ROOT / "levels" / "small.json"


@pytest.fixture
def fifo(tmp_path):
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs on this system")
    path = tmp_path / "pipe.json"
    os.mkfifo(path)
    return path


def fake_stdin(monkeypatch, data: bytes):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(data)))


# ---------------------------------------------------------------------------------------
# read_input

def test_a_regular_file_is_read_whole(tmp_path):
    path = tmp_path / "a.bin"
    path.write_bytes(b"\x00abc" * 100)
    assert read_input(path, 400) == b"\x00abc" * 100


def test_a_fifo_is_refused_without_being_opened(fifo):
    with pytest.raises(InputError) as info:
        read_input(fifo, 1000)
    assert str(info.value) == f"{fifo}: is a FIFO (named pipe), not a regular file; refusing to read it"


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_dev_zero_is_refused():
    with pytest.raises(InputError, match=r"^/dev/zero: is a device, not a regular file"):
        read_input("/dev/zero", 1000)


def test_a_directory_is_refused(tmp_path):
    with pytest.raises(InputError, match=r": is a directory"):
        read_input(tmp_path, 1000)


def test_a_missing_file_says_so(tmp_path):
    with pytest.raises(InputError) as info:
        read_input(tmp_path / "nowhere", 1000)
    assert info.value.reason == "no such file" and info.value.path == str(tmp_path / "nowhere")


def test_a_file_over_the_limit_is_refused(tmp_path):
    path = tmp_path / "big.json"
    path.write_bytes(b" " * 101)
    assert read_input(path, 101) == b" " * 101
    with pytest.raises(InputError, match=r"too large \(101 bytes, more than the limit of 100"):
        read_input(path, 100)


def test_open_regular_refuses_what_read_input_refuses(tmp_path, fifo):
    with pytest.raises(InputError, match="is a FIFO"):
        open_regular(fifo)
    path = tmp_path / "a.bin"
    path.write_bytes(b"abc")
    with open_regular(path) as f:
        assert f.read() == b"abc" and f.name == str(path)   # a name, not a descriptor


def test_a_dash_reads_standard_input(monkeypatch):
    fake_stdin(monkeypatch, b"hello")
    assert read_input("-", 5) == b"hello"


def test_standard_input_over_the_limit_is_refused(monkeypatch):
    fake_stdin(monkeypatch, b"x" * 6)
    with pytest.raises(InputError, match=r"^-: too large \(more than the limit of 5 bytes\)"):
        read_input("-", 5)


# ---------------------------------------------------------------------------------------
# Loading a level

def test_a_level_from_standard_input(monkeypatch):
    fake_stdin(monkeypatch, SMALL.read_bytes())
    level = load_level("-")
    assert level == load_level(SMALL)
    assert (level.source, level.source_dir) == ("<stdin>", None)


def test_a_level_from_standard_input_has_no_file_name_to_be_named_after(monkeypatch):
    data = json.loads(SMALL.read_bytes())
    del data["name"]
    fake_stdin(monkeypatch, json.dumps(data).encode())
    assert load_level("-").name == ""


def test_a_fifo_is_not_a_level(fifo):
    with pytest.raises(LevelError) as info:
        load_level(fifo)
    assert str(info.value).startswith(f"{fifo}: (root): is a FIFO")


def test_deep_nesting_from_a_file_is_one_line(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(LevelError) as info:
        load_level(path)
    assert str(info.value).startswith(f"{path}: (root): malformed JSON: ")
    assert "\n" not in str(info.value)


# ---------------------------------------------------------------------------------------
# The command line

def test_stats_reads_a_level_piped_to_a_dash():
    done = subprocess.run([sys.executable, "-m", "wallbsp", "stats", "-", "--json"],
                          input=SMALL.read_bytes(), capture_output=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["level_sha256"] == content_hash(load_level(SMALL))


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, err.splitlines()


@pytest.mark.parametrize("command", ["compile", "stats", "render"])
def test_a_fifo_is_refused_by_the_cli(tmp_path, capsys, fifo, command):
    out = tmp_path / "out.bin"
    code, lines = run(capsys, command, fifo, *([] if command == "stats" else ["-o", out]))
    assert code == 2 and len(lines) == 1, lines
    assert lines[0].endswith(f"{fifo}: (root): is a FIFO (named pipe), not a regular file; "
                             f"refusing to read it")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe.json"]   # nothing written


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="no /dev/zero")
def test_dev_zero_and_a_directory_are_refused_by_the_cli(tmp_path, capsys):
    for source, what in (("/dev/zero", "is a device"), (tmp_path, "is a directory")):
        code, lines = run(capsys, "stats", source)
        assert code == 2 and len(lines) == 1 and what in lines[0], lines


def test_a_tree_on_standard_input_is_one_line(tmp_path, capsys, monkeypatch):
    tree = tmp_path / "small.wbsp"
    assert run(capsys, "compile", SMALL, "-o", tree)[0] == 0
    fake_stdin(monkeypatch, tree.read_bytes())
    code, lines = run(capsys, "stats", "-")
    assert code == 2 and len(lines) == 1 and lines[0].startswith("<stdin>: "), lines
