"""The prompt templates ship inside the package: sdist → wheel → fresh venv → load every template.

One build only. The wheel is built from the unpacked sdist in the dev profile (the templates do
not care how fast the core is, and a dev build is several times quicker), with cargo's target
directory kept under the repository's ``target/`` so later runs reuse the compiled dependencies.
The fresh venv gets the wheel with ``--no-deps`` (no network); the running interpreter's
site-packages are appended to its path for the dependencies, after its own site-packages, so
``mansion`` itself can only come from the wheel — which the check asserts.
"""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import tarfile
import venv
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]

CHECK = """
import mansion, sys
from pathlib import Path
from mansion.agents.prompts import PROMPTS, load_prompt
assert Path(mansion.__file__).resolve().is_relative_to(Path(sys.prefix).resolve()), mansion.__file__
for name in PROMPTS:
    p = load_prompt(name)
    p.render(**{k: "x" for k in p.placeholders()})
print("loaded", len(PROMPTS))
"""


def _run(cmd: list[str], **kw: object) -> subprocess.CompletedProcess[str]:
    result = subprocess.run(cmd, capture_output=True, text=True, **kw)  # type: ignore[call-overload]
    assert result.returncode == 0, f"{' '.join(cmd)} failed:\n{result.stdout}\n{result.stderr}"
    return result


@pytest.mark.slow
def test_templates_load_from_a_wheel_built_from_the_sdist(tmp_path: Path) -> None:
    pytest.importorskip("maturin")
    env = {**os.environ, "CARGO_TARGET_DIR": str(ROOT / "target" / "wheel-from-sdist")}
    _run([sys.executable, "-m", "maturin", "sdist", "--out", str(tmp_path / "sdist")], cwd=ROOT, env=env)
    (sdist,) = (tmp_path / "sdist").glob("mansion-*.tar.gz")
    with tarfile.open(sdist) as tar:
        names = tar.getnames()
        assert any(n.endswith("python/mansion/prompts/seed_planner.md") for n in names), names
        tar.extractall(tmp_path / "src", filter="data")
    (src,) = (tmp_path / "src").iterdir()
    _run(
        [sys.executable, "-m", "maturin", "build", "--profile", "dev", "--out", str(tmp_path / "wheel")],
        cwd=src, env=env,
    )
    (wheel,) = (tmp_path / "wheel").glob("mansion-*.whl")

    fresh = tmp_path / "venv"
    venv.create(fresh, with_pip=True)
    py = fresh / "bin" / "python"
    _run([str(py), "-m", "pip", "install", "--no-deps", "--no-index", "--quiet", str(wheel)])
    site = _run([str(py), "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"]).stdout.strip()
    ours = {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"]}
    Path(site, "_test_deps.pth").write_text("\n".join(sorted(ours)) + "\n")
    out = _run([str(py), "-c", CHECK], cwd=tmp_path).stdout
    from mansion.agents.prompts import PROMPTS

    assert f"loaded {len(PROMPTS)}" in out
