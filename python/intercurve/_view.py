"""The interactive view of a problem or a trace in a notebook
(_repr_html_): the library's HTML page (a three.js scene) in an iframe,
or, where the library writes no HTML, its SVG picture."""

import base64
import html
import os
import tempfile

from ._lib import IC_ERR_INVALID, InputError

# points: the picture's size in a notebook cell
VIEW_SIZE = (960, 540)


def view_html(draw, size=VIEW_SIZE):
    """HTML for a notebook: draw(path, size=...) writes the picture to path
    (ic_plot_write: the format by the extension). An .html page goes into
    an iframe's srcdoc; when the library does not know the format (an
    InputError of an invalid argument) an .svg picture is embedded as an
    image instead."""
    with tempfile.TemporaryDirectory(prefix="intercurve-view-") as d:
        page = os.path.join(d, "view.html")
        try:
            draw(page, size=size)
        except InputError as e:
            if e.code != IC_ERR_INVALID:
                raise
            return _svg_image(draw, os.path.join(d, "view.svg"), size)
        with open(page, encoding="utf-8") as f:
            text = f.read()
    return ('<iframe srcdoc="%s" style="width: 100%%; max-width: %dpx; height: %dpx; '
            'border: 0" sandbox="allow-scripts"></iframe>'
            % (html.escape(text, quote=True), size[0], size[1] + 20))


def _svg_image(draw, path, size):
    draw(path, size=size)
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    # an image, not inline SVG: the glyph ids of two pictures in one
    # notebook would collide
    return '<img src="data:image/svg+xml;base64,%s" width="%d" height="%d" alt="intercurve">' % (
        data, size[0], size[1])
