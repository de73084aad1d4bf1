"""Loads matplotlib's pyplot for the plotting scripts (imported by them; not run on its own)."""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def import_pyplot(script, argv):
    """Installs Debian's python3-matplotlib when missing and returns pyplot on the Agg backend.
    `script` and `argv` re-run the calling script under /usr/bin/python3 when another python3 (pyenv)
    is first on PATH: it cannot see Debian's packages."""
    subprocess.run([os.path.join(HERE, "ensure-packages.sh"), "python3-matplotlib"], check=True)
    try:
        import matplotlib
    except ImportError:
        if sys.executable != "/usr/bin/python3":
            os.execv("/usr/bin/python3", ["/usr/bin/python3", os.path.abspath(script)] + argv)
        raise
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt
