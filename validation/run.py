"""Runs the validation against programs and papers written elsewhere: one
script per reference, each writing its table (validation/results/NAME.csv and
.md) and figure (docs/src/figures/validation/NAME.png), and exiting with 1 when
a comparison leaves its stated tolerance.

    python validation/run.py              # every script
    python validation/run.py slammer      # some of them
    python validation/run.py mujoco_stack --sequence   # one script, with its option

It makes its own virtual environment (validation/.venv, kept between runs)
with the references from PyPI (validation/requirements.txt), builds the
`rocking` command (cargo build --release --locked -p rocking-cli), and runs
each script with that environment's Python. Needs Python >= 3.9 with venv,
Rust, and PyPI. ROCKING_VALIDATION_VENV puts the environment elsewhere.
"""

import os
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
SCRIPTS = ["slammer", "housner", "makris", "mujoco_tower", "stack_impacts", "mujoco_stack"]


def environment():
    """The virtual environment's Python, made and filled when the requirements changed."""
    venv = pathlib.Path(os.environ.get("ROCKING_VALIDATION_VENV", HERE / ".venv"))
    python = venv / ("Scripts/python.exe" if os.name == "nt" else "bin/python")
    requirements = (HERE / "requirements.txt").read_text()
    stamp = venv / "requirements.installed"
    if not python.exists():
        print(f"== making the virtual environment {venv}")
        subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    if not stamp.exists() or stamp.read_text() != requirements:
        print("== installing the references from PyPI (validation/requirements.txt)")
        subprocess.run(
            [str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check", "-r", str(HERE / "requirements.txt")],
            check=True,
        )
        stamp.write_text(requirements)
    return python


def main():
    options = [arg for arg in sys.argv[1:] if arg.startswith("--")]
    wanted = [arg for arg in sys.argv[1:] if not arg.startswith("--")] or SCRIPTS
    unknown = [name for name in wanted if name not in SCRIPTS]
    if unknown:
        sys.exit(f"unknown script(s): {', '.join(unknown)}; the scripts are {', '.join(SCRIPTS)}")
    if options and len(wanted) != 1:
        sys.exit(f"options ({' '.join(options)}) go to one script: name it, e.g. mujoco_stack --sequence")
    python = environment()
    target = pathlib.Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target"))
    print("== building the rocking command (release)")
    subprocess.run(["cargo", "build", "--release", "--locked", "-p", "rocking-cli", "--bin", "rocking"], cwd=ROOT, check=True)
    env = dict(os.environ, ROCKING_CLI=str(target / "release" / "rocking"), MPLBACKEND="Agg")
    failed = []
    for name in wanted:
        print(f"== {name}")
        start = time.monotonic()
        done = subprocess.run([str(python), str(HERE / f"{name}.py"), *options], cwd=HERE, env=env)
        print(f"   {name}: {'ok' if done.returncode == 0 else 'FAILED'} in {time.monotonic() - start:.0f} s")
        if done.returncode != 0:
            failed.append(name)
    if failed:
        print(f"outside tolerance or failed: {', '.join(failed)}")
        sys.exit(1)
    print("every comparison within its tolerance; tables in validation/results/, figures in docs/src/figures/validation/")


if __name__ == "__main__":
    main()
