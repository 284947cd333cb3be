"""``python -m xaml3d``: the same command line as the ``xaml3d`` script."""

from xaml3d.cli import main

if __name__ == "__main__":
    main()
