#!/usr/bin/python3
"""Writes a small ONNX network with EAST's interface, for the OCR tests and benchmark.

    make_east_test_model.py OUTPUT.onnx

Input 1x3xHxW (RGB minus EAST's channel means, as cv::dnn::TextDetectionModel_EAST feeds it);
outputs "scores" 1x1xH/4xW/4 and "geometry" 1x5xH/4xW/4 (distances from each cell to the box's
top, right, bottom and left edge in input pixels, then the angle). OpenCV hands a network's outputs
to the EAST decoder in name order and takes the first as geometry, hence the names.

The weights are set by hand, not trained: the network finds dark strokes that are darker than
their surroundings, joins neighbouring strokes into blobs (a word, or a few close words), measures
each blob's half-width and half-height by repeated erosion, and scores only the cells at a blob's
centre, whose geometry spans the whole blob; blobs narrower than high (strokes of clutter) are not
scored. So model loading, the forward pass, decoding,
non-maximum suppression and recognition all run for real and find real words on dark-on-light
text whose capitals are roughly 12-30 px high at the network's input size (choose the
EAST input size accordingly). It is no substitute for the public EAST model
(frozen_east_text_detection.pb): accuracy figures for EAST need that model.

Needs Debian's python3-onnx (run with /usr/bin/python3).
"""
import sys

import numpy as np
import onnx
from onnx import TensorProto, helper, numpy_helper

EAST_MEAN_RGB = (123.68, 116.78, 103.94)
CELL = 4                 # EAST's output stride
LOCAL_WINDOW = 9         # cells (36 px) over which "darker than the surroundings" is judged
DARKNESS_OFFSET = 12.0   # grey levels below the local mean before a cell counts as ink
DARKNESS_RANGE = 30.0    # grey levels over which ink goes from 0 to 1
DENSITY_WINDOW = (3, 3)  # cells averaged to bridge the gaps between letters
DENSITY_THRESHOLD = 0.12
MAX_HALF_WIDTH = 100     # cells: blobs (words, or lines) up to 800 px wide are measured exactly
MAX_HALF_HEIGHT = 16     # cells: up to 128 px high


class Graph:
    def __init__(self):
        self.nodes, self.initializers, self.count = [], [], 0

    def name(self, stem):
        self.count += 1
        return f"{stem}_{self.count}"

    def constant(self, value, shape=()):
        name = self.name("const")
        self.initializers.append(numpy_helper.from_array(np.full(shape, value, dtype=np.float32), name))
        return name

    def op(self, op_type, inputs, output=None, **attributes):
        output = output or self.name(op_type.lower())
        self.nodes.append(helper.make_node(op_type, inputs, [output], **attributes))
        return output

    def sub(self, a, b):
        return self.op("Sub", [a, b])

    def add(self, a, b):
        return self.op("Add", [a, b])

    def mul(self, a, b):
        return self.op("Mul", [a, b])

    def scale(self, x, factor, offset=0.0):
        scaled = self.mul(x, self.constant(factor))
        return self.add(scaled, self.constant(offset)) if offset else scaled

    def relu(self, x):
        return self.op("Relu", [x])

    def saturate(self, x):
        """Clamps to 0..1 with two ReLUs (Clip's min/max inputs vary between ONNX opsets)."""
        return self.sub(self.relu(x), self.relu(self.scale(x, 1.0, -1.0)))

    def max_pool(self, x, kernel):
        pads = [k // 2 for k in kernel] * 2
        return self.op("MaxPool", [x], kernel_shape=list(kernel), pads=pads, strides=[1, 1])

    def average_pool(self, x, kernel, stride=1, pad=True):
        pads = [k // 2 for k in kernel] * 2 if pad else [0, 0, 0, 0]
        return self.op("AveragePool", [x], kernel_shape=list(kernel), pads=pads,
                       strides=[stride, stride], count_include_pad=0)

    def half_extent(self, mask, kernel, steps):
        """Cells from each cell to its blob's nearer edge along one axis, counting the cell itself:
        the sum of the mask eroded 0..steps times (erosion = max-pool of the negated mask)."""
        negated = self.scale(mask, -1.0)
        total = negated
        for _ in range(steps):
            negated = self.max_pool(negated, kernel)
            total = self.add(total, negated)
        return self.scale(total, -1.0)

    def is_centre(self, extent, kernel):
        """1 where `extent` is within one cell of its local maximum along the axis, else 0."""
        peak = self.max_pool(extent, kernel)
        return self.saturate(self.scale(self.sub(peak, extent), -1.0, 2.0))


def build():
    g = Graph()
    gray_weights = numpy_helper.from_array(np.full((1, 3, 1, 1), 1.0 / 3.0, dtype=np.float32), "gray_w")
    gray_bias = numpy_helper.from_array(np.array([sum(EAST_MEAN_RGB) / 3.0], dtype=np.float32), "gray_b")
    g.initializers += [gray_weights, gray_bias]
    gray = g.op("Conv", ["image", "gray_w", "gray_b"], kernel_shape=[1, 1])  # back to 0..255

    cells = g.average_pool(gray, (CELL, CELL), stride=CELL, pad=False)
    surroundings = g.average_pool(cells, (LOCAL_WINDOW, LOCAL_WINDOW))
    darker_by = g.sub(surroundings, cells)
    ink = g.saturate(g.scale(darker_by, 1.0 / DARKNESS_RANGE, -DARKNESS_OFFSET / DARKNESS_RANGE))
    density = g.average_pool(ink, DENSITY_WINDOW)
    blob = g.saturate(g.scale(density, 50.0, -50.0 * DENSITY_THRESHOLD))
    # Closing (dilate, then erode) fills the gaps between letters and holes in them; one more cell
    # up and down leaves room for ascenders and descenders.
    blob = g.scale(g.max_pool(g.scale(g.max_pool(blob, (3, 3)), -1.0), (3, 3)), -1.0)
    blob = g.max_pool(blob, (3, 1))

    half_width = g.half_extent(blob, (1, 3), MAX_HALF_WIDTH)
    half_height = g.half_extent(blob, (3, 1), MAX_HALF_HEIGHT)

    centre = g.mul(g.is_centre(half_width, (1, 5)), g.is_centre(half_height, (5, 1)))
    # Words are at least 3 cells high and wider than high; thin strokes of clutter (lines, rims)
    # are not.
    big_enough = g.saturate(g.scale(half_height, 1.0, -1.0))
    wide_enough = g.saturate(g.scale(g.sub(half_width, half_height), 1.0, 1.0))
    g.op("Mul", [g.mul(blob, centre), g.mul(big_enough, wide_enough)], output="scores")

    # A cell covers input pixels [CELL*x, CELL*x + CELL); the decoder places it at CELL*x.
    top = g.scale(half_height, CELL, -CELL)
    bottom = g.scale(half_height, CELL)
    left = g.scale(half_width, CELL, -CELL)
    right = g.scale(half_width, CELL)
    angle = g.scale(half_width, 0.0)
    g.op("Concat", [top, right, bottom, left, angle], output="geometry", axis=1)

    graph = helper.make_graph(
        g.nodes, "east_test_model",
        [helper.make_tensor_value_info("image", TensorProto.FLOAT, [1, 3, "height", "width"])],
        [helper.make_tensor_value_info("geometry", TensorProto.FLOAT, [1, 5, "cells_y", "cells_x"]),
         helper.make_tensor_value_info("scores", TensorProto.FLOAT, [1, 1, "cells_y", "cells_x"])],
        g.initializers)
    model = helper.make_model(graph, producer_name="libubii-tests",
                              opset_imports=[helper.make_opsetid("", 11)])
    model.ir_version = 6
    onnx.checker.check_model(model)
    return model


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    onnx.save(build(), sys.argv[1])
