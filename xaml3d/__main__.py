"""``python -m xaml3d``: the same command line as the ``xaml3d`` script."""

from xaml3d.cli import run

if __name__ == "__main__":
    run()
