#!/usr/bin/env python3
"""Checks that the library's headers include only headers of lower layers.

The folders of include/diffuv/ are layers (doc/design.md, "Layers"): a header
may include a header of its own folder or of a folder of a lower layer, never
one of its own layer's other folders or of a higher layer. It also checks that
the umbrella header diffuv/diffuv.h includes every public header of the core
target (all but internal/ and render/, which is the optional target that needs
stb) and nothing else, and that no header of the core target includes render/.

usage: scripts/check_layers.py [ROOT]      (ROOT: the repository, default: this script's parent)
Prints one line per violation and exits 1 if there is any; exits 0 and prints
a one-line summary otherwise.
"""
import os
import re
import sys

# Lowest first. Folders of one layer know nothing of each other.
LAYERS = [
    ["core", "internal"],     # the vocabulary: errors, sides, colours; helpers that are not API
    ["io", "graph"],          # files -> soups, labels, corners; distances on any BGL graph
    ["patches"],              # labels -> disc patches, their sides and corners
    ["layout"],               # the four-sided layout, and disc_patches(): every way to get patches
    ["atlas", "metrics"],     # the (u,v) container (array + kd-tree); the distortion of a map
    ["parameterization"],     # diffusion coordinates, the fold repair, whole meshes into an atlas
    ["cgal", "correspondence", "output", "render"],  # uses
]
OPTIONAL = {"render"}  # the diffuv::render target (stb); the core target must not include it
UMBRELLA = "diffuv.h"
# Headers a program includes in exactly one source file (they define the
# global operator new): public, but never in the umbrella header.
INCLUDE_ONCE = {"core/huge_page_allocation.h"}

INCLUDE = re.compile(r'^\s*#\s*include\s*<diffuv/([^>]+)>', re.M)


def layer_of(folder):
    for i, folders in enumerate(LAYERS):
        if folder in folders:
            return i
    return None


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    base = os.path.join(root, "include", "diffuv")
    problems = []
    headers = []
    for folder, _, files in os.walk(base):
        for name in files:
            if name.endswith(".h"):
                headers.append(os.path.relpath(os.path.join(folder, name), base))
    headers.sort()
    for header in headers:
        parts = header.split(os.sep)
        if len(parts) == 1:
            if header != UMBRELLA:
                problems.append("%s: a header outside every layer's folder" % header)
            continue
        folder = parts[0]
        layer = layer_of(folder)
        if layer is None:
            problems.append("%s: the folder %s/ is in no layer (scripts/check_layers.py, LAYERS)" % (header, folder))
            continue
        with open(os.path.join(base, header), encoding="utf-8") as f:
            text = f.read()
        for included in INCLUDE.findall(text):
            if not os.path.exists(os.path.join(base, included)):
                problems.append("%s: includes <diffuv/%s>, which does not exist" % (header, included))
                continue
            other = included.split("/")[0]
            if other == folder:
                continue
            if included == UMBRELLA:
                problems.append("%s: includes the umbrella header" % header)
                continue
            other_layer = layer_of(other)
            if other_layer is None or other_layer >= layer:
                problems.append("%s (layer %d, %s/) includes <diffuv/%s> (layer %s, %s/): a header may include only "
                                "its own folder or lower layers" % (header, layer, folder, included, other_layer, other))
            if other in OPTIONAL and folder not in OPTIONAL:
                problems.append("%s: includes <diffuv/%s>, of the optional render target" % (header, included))
    # The umbrella header: every public header of the core target, nothing else.
    with open(os.path.join(base, UMBRELLA), encoding="utf-8") as f:
        listed = set(INCLUDE.findall(f.read()))
    public = {h.replace(os.sep, "/") for h in headers
              if os.sep in h and h.split(os.sep)[0] not in OPTIONAL | {"internal"} and os.sep + "internal" + os.sep not in h}
    for once in sorted(INCLUDE_ONCE & listed):
        problems.append("%s: includes <diffuv/%s>, which a program includes in one source file only" % (UMBRELLA, once))
    public -= INCLUDE_ONCE
    for missing in sorted(public - listed):
        problems.append("%s: does not include <diffuv/%s>" % (UMBRELLA, missing))
    for extra in sorted(listed - public):
        problems.append("%s: includes <diffuv/%s>, which is not a public header of the core target" % (UMBRELLA, extra))
    for p in problems:
        print(p)
    if problems:
        print("check_layers: %d problem(s)" % len(problems))
        return 1
    print("check_layers: %d headers in %d layers, every include points down; %s includes the %d public headers"
          % (len(headers), len(LAYERS), UMBRELLA, len(public)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
