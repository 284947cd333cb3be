"""The Python floor of "XAML in, PNG out": what any XAML-to-PNG tool in Python pays at least.

Read the file, parse it with lxml, convert every number-list attribute of every element to a
numpy array (one ``np.fromstring`` per attribute, commas made blanks first), and write a blank
PNG of the given size with Pillow at the same zlib level xaml3d uses. No scene is built, nothing
is drawn. ``bench_issue.py`` runs this as a whole process beside every case, in the same run.

    python benchmarks/floor.py SCENE.xaml OUT.png WIDTH HEIGHT
    python benchmarks/floor.py SCENE.xaml -                  # reading only (info / validate)
"""

import sys

import numpy as np
from lxml import etree

NUMBER_LISTS = ("Positions", "Normals", "TextureCoordinates", "TriangleIndices")


def read(path: str) -> int:
    with open(path, "rb") as fh:
        root = etree.fromstring(fh.read(), etree.XMLParser(huge_tree=True))
    count = 0
    for el in root.iter():
        for name in NUMBER_LISTS:
            text = el.get(name)
            if text:
                count += np.fromstring(text.replace(",", " "), sep=" ").size
    return count


def main() -> None:
    read(sys.argv[1])
    if sys.argv[2] != "-":
        from PIL import Image

        w, h = int(sys.argv[3]), int(sys.argv[4])
        Image.fromarray(np.zeros((h, w, 4), np.uint8), "RGBA").save(sys.argv[2], compress_level=1)


if __name__ == "__main__":
    main()
