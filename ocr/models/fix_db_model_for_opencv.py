#!/usr/bin/env python3
"""Rewrites PaddleOCR's PP-OCRv4 DB text detector (ONNX, opset 11) so that OpenCV 4.6 loads it.

The exported graph has 24 Clip nodes whose min and max are inputs (opset 11 style), all of them
constants; OpenCV 4.6's ONNX importer accepts only the older form with `min`/`max` attributes
(ONNXImporter::parseClip requires one input). Each such Clip gets its constants as attributes and
keeps only its data input; nothing else changes, so the network computes the same function.

    fix_db_model_for_opencv.py IN.onnx OUT.onnx
"""
import sys

import onnx
from onnx import numpy_helper


def constant_values(graph):
    values = {}
    for node in graph.node:
        if node.op_type == "Constant":
            for attribute in node.attribute:
                if attribute.name == "value":
                    values[node.output[0]] = numpy_helper.to_array(attribute.t)
    for initializer in graph.initializer:
        values[initializer.name] = numpy_helper.to_array(initializer)
    return values


def scalar(values, name, clip):
    if name not in values:
        sys.exit(f"{clip.name}: bound {name} is not a constant; this model cannot be converted")
    array = values[name]
    if array.size != 1:
        sys.exit(f"{clip.name}: bound {name} is not a scalar")
    return float(array.reshape(-1)[0])


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: fix_db_model_for_opencv.py IN.onnx OUT.onnx")
    model = onnx.load(sys.argv[1])
    values = constant_values(model.graph)
    converted = 0
    for node in model.graph.node:
        if node.op_type != "Clip" or len(node.input) == 1:
            continue
        bounds = list(node.input[1:])
        names = ("min", "max")
        for name, bound in zip(names, bounds):
            if bound:
                node.attribute.append(
                    onnx.helper.make_attribute(name, scalar(values, bound, node)))
        del node.input[1:]
        converted += 1
    # Constants only the Clips used would be dangling inputs-less nodes: harmless, but drop them.
    used = {name for node in model.graph.node for name in node.input}
    kept = [n for n in model.graph.node
            if n.op_type != "Constant" or any(o in used for o in n.output)]
    del model.graph.node[:]
    model.graph.node.extend(kept)
    # No onnx.checker here: attribute bounds are not valid opset-11 ONNX, only what OpenCV reads.
    onnx.save(model, sys.argv[2])
    print(f"fix_db_model_for_opencv: {converted} Clip nodes converted")


if __name__ == "__main__":
    main()
