"""prt's .pfm images (32-bit float linear RGB, every bit as in its .exr), read into Blender's
render-pass layout: RGBA floats, bottom row first, which is PFM's row order too."""
import numpy as np


def read_rgba(path, width, height):
    """The pixels of PATH as a flat float32 array of WIDTH x HEIGHT x 4 (alpha 1)."""
    with open(path, "rb") as f:
        data = f.read()
    header = []
    at = 0
    while len(header) < 4:  # "PF", width, height, scale, separated by white space
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while end < len(data) and not data[end:end + 1].isspace():
            end += 1
        header.append(data[at:end].decode("ascii", "replace"))
        at = end
    at += 1  # the single white-space byte before the pixels
    if header[0] != "PF" or int(header[1]) != width or int(header[2]) != height:
        raise ValueError("%s: %s %sx%s, not a PF image of %dx%d" % (path, header[0], header[1],
                                                                    header[2], width, height))
    order = "<" if float(header[3]) < 0 else ">"
    rgb = np.frombuffer(data, dtype=order + "f4", count=width * height * 3, offset=at)
    rgba = np.ones((width * height, 4), dtype=np.float32)
    rgba[:, :3] = rgb.reshape(-1, 3)
    return rgba.ravel()
