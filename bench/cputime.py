"""The CPU time of whole processes, for the benchmarks that time curvefig
beside other programs (peers.py, surfaces_pgfplots.py,
startup_compare.py), and the pdflatex run they time it against.

cpu_of starts each command by posix_spawn: a fork() of the Python process
would charge each command some 6 ms of tearing down its copy of Python's
address space (an empty program: 9.6 ms after fork, 3.1 ms after
posix_spawn, medians of 15 on this machine).
"""
import os
import shutil
import subprocess


def cpu_of(argv, cwd=None):
    """Run argv (in cwd, default the current directory; its standard
    streams on /dev/null); the CPU seconds (user + system) of it and its
    children.  RuntimeError when it is not found or fails."""
    here = None
    if cwd is not None:
        # posix_spawn has no chdir action in Python: the parent moves
        # there for the spawn (these scripts run one thread)
        here = os.getcwd()
        os.chdir(cwd)
    try:
        path = shutil.which(argv[0])
        if path is None:
            raise RuntimeError("not found: %s" % argv[0])
        pid = os.posix_spawn(path, argv, os.environ,
                             file_actions=[(os.POSIX_SPAWN_OPEN, k,
                                            os.devnull, os.O_RDWR, 0)
                                           for k in (0, 1, 2)])
    finally:
        if here is not None:
            os.chdir(here)
    _, status, ru = os.wait4(pid, 0)
    if status != 0:
        raise RuntimeError("failed (status %d): %s" % (status, " ".join(argv)))
    return ru.ru_utime + ru.ru_stime


def have_pdflatex(*packages):
    """Whether pdflatex is installed, with each of packages (file names
    such as "pgfplots.sty", found by kpsewhich)."""
    if not shutil.which("pdflatex"):
        return False
    for p in packages:
        found = subprocess.run(["kpsewhich", p], stdout=subprocess.PIPE,
                               check=False).stdout.strip()
        if found == b"":
            return False
    return True


def pdflatex(tex):
    """The command that typesets tex (a file of the directory it runs in) to
    PDF, stopping at the first error, without asking."""
    return ["pdflatex", "-interaction=batchmode", "-halt-on-error", tex]
