#!/usr/bin/python3
"""Compares two protobuf descriptor sets message by message and enum by enum.

Usage: compare_schemas.py REFERENCE.pb OURS.pb

Every message and enum of either set must exist in the other with the same fields (number, name,
JSON name, type, label, oneof membership, referenced type, packed-ness) and the same enum values.
Prints one line per difference naming the message and field; exits 1 if there is any.
"""
import sys

from google.protobuf import descriptor_pb2

FieldType = descriptor_pb2.FieldDescriptorProto


def load(path):
    fds = descriptor_pb2.FileDescriptorSet()
    with open(path, "rb") as f:
        fds.ParseFromString(f.read())
    return fds


def collect(fds):
    """Returns ({full message name: DescriptorProto}, {full enum name: EnumDescriptorProto})."""
    messages, enums = {}, {}

    def walk(prefix, message):
        name = f"{prefix}.{message.name}"
        messages[name] = message
        for nested in message.nested_type:
            walk(name, nested)
        for enum in message.enum_type:
            enums[f"{name}.{enum.name}"] = enum

    for file in fds.file:
        if file.package.startswith("google."):
            continue
        for message in file.message_type:
            walk(file.package, message)
        for enum in file.enum_type:
            enums[f"{file.package}.{enum.name}"] = enum
    return messages, enums


def field_facts(message, field):
    oneof = None
    if field.HasField("oneof_index") and not field.proto3_optional:
        oneof = message.oneof_decl[field.oneof_index].name
    packed = field.options.packed if field.options.HasField("packed") else None
    return {
        "name": field.name,
        "json_name": field.json_name,
        "type": FieldType.Type.Name(field.type),
        "label": FieldType.Label.Name(field.label),
        "oneof": oneof,
        "type_name": field.type_name.lstrip("."),
        "proto3_optional": field.proto3_optional,
        "packed": packed,
    }


def compare(reference, ours):
    problems = []
    ref_messages, ref_enums = collect(reference)
    our_messages, our_enums = collect(ours)

    for name in sorted(ref_messages.keys() - our_messages.keys()):
        problems.append(f"message {name}: missing in ours")
    for name in sorted(our_messages.keys() - ref_messages.keys()):
        problems.append(f"message {name}: not in the reference")
    for name in sorted(ref_messages.keys() & our_messages.keys()):
        ref_fields = {f.number: f for f in ref_messages[name].field}
        our_fields = {f.number: f for f in our_messages[name].field}
        for number in sorted(ref_fields.keys() | our_fields.keys()):
            if number not in our_fields:
                problems.append(f"message {name} field {ref_fields[number].name} = {number}: missing in ours")
                continue
            if number not in ref_fields:
                problems.append(f"message {name} field {our_fields[number].name} = {number}: not in the reference")
                continue
            ref = field_facts(ref_messages[name], ref_fields[number])
            our = field_facts(our_messages[name], our_fields[number])
            for key in ref:
                if ref[key] != our[key]:
                    problems.append(
                        f"message {name} field {ref['name']} = {number}: {key} is {our[key]!r}, reference has {ref[key]!r}")

    for name in sorted(ref_enums.keys() - our_enums.keys()):
        problems.append(f"enum {name}: missing in ours")
    for name in sorted(our_enums.keys() - ref_enums.keys()):
        problems.append(f"enum {name}: not in the reference")
    for name in sorted(ref_enums.keys() & our_enums.keys()):
        ref_values = {v.name: v.number for v in ref_enums[name].value}
        our_values = {v.name: v.number for v in our_enums[name].value}
        if ref_values != our_values:
            problems.append(f"enum {name}: values are {our_values}, reference has {ref_values}")

    return problems, len(ref_messages), len(ref_enums)


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    problems, n_messages, n_enums = compare(load(sys.argv[1]), load(sys.argv[2]))
    for problem in problems:
        print(problem)
    if problems:
        print(f"schema conformance: {len(problems)} difference(s)")
        return 1
    print(f"schema conformance: {n_messages} messages and {n_enums} enums identical")
    return 0


if __name__ == "__main__":
    sys.exit(main())
