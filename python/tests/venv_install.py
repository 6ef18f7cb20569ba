"""The module in a fresh virtual environment: `pip install
--no-build-isolation .` of the checkout, then import it there from
another directory, evaluate a curve and render a figure.

    venv_install.py PYTHON SOURCE WORKDIR

The environment is made anew in WORKDIR/venv (--system-site-packages for
Debian's numpy and meson-python, --without-pip: Debian's pip runs it); the
build directory WORKDIR/pip-build is kept between runs, so only the first
run builds the whole project (pyproject.toml: no unit tests)."""

import os
import shutil
import subprocess
import sys
import time


def main():
    python, source, work = sys.argv[1:4]
    venv = os.path.join(work, "venv")
    shutil.rmtree(venv, ignore_errors=True)
    os.makedirs(work, exist_ok=True)
    start = time.monotonic()
    subprocess.run([python, "-m", "venv", "--system-site-packages",
                    "--without-pip", venv], check=True)
    vpy = os.path.join(venv, "bin", "python")
    env = dict(os.environ)
    for k in ("PYTHONPATH", "PYTHONHOME"):
        env.pop(k, None)
    subprocess.run([vpy, "-m", "pip", "install", "--quiet",
                    "--no-build-isolation", "--no-deps", "--no-index",
                    "--config-settings=builddir="
                    + os.path.join(work, "pip-build"),
                    "--config-settings=setup-args=-Dwasm=disabled",
                    source], check=True, env=env, cwd=work)
    check = (
        "import curvefig, os, sys\n"
        "assert curvefig.__file__.startswith(sys.prefix), curvefig.__file__\n"
        "c = curvefig.Bezier([[0, 0], [1, 2], [2, 0]])\n"
        "assert c.eval(0.5).tolist() == [1.0, 1.0]\n"
        "f = curvefig.Figure('v'); f.curve(c)\n"
        "assert f.render('svg').startswith(b'<?xml')\n"
        "print('imported', curvefig.__file__)\n")
    subprocess.run([vpy, "-c", check], check=True, env=env, cwd=work)
    print("venv and install: %.1f s" % (time.monotonic() - start))


if __name__ == "__main__":
    main()
