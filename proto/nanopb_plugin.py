#!/usr/bin/python3
"""protoc plugin: Debian's nanopb generator behind three steps of our own on the request.

1. Schema reduction (UBII_SCHEMA_SPEC names a proto/schemas/*.schema file): the fields a `keep`
   line does not name are deleted from that message, and imports nothing refers to any more are
   dropped. Fields are only ever deleted, never renumbered or retyped, so a reduced schema reads
   and writes the same bytes as the full one; fields it lacks are skipped when decoding, as
   protobuf skips every unknown field.
2. Keyword rename: upstream's TopicDataRecord has oneof members named `double`, `bool` and `float`.
   nanopb 0.4.7 emits struct members with exactly those names, which is not valid C. Any field or
   oneof name that is a C or C++ keyword gets "_" appended (the rename protoc's own C++ generator
   applies). Only the C identifiers change; the .proto files keep upstream's names (which are also
   the proto-JSON names).
3. ubii/record_types.h: the TopicDataRecord value members this schema has, as an X-macro list
   (X(NAME, field number)), from which the core makes its record type enum and tables, so the core
   names no record type the schema lacks.
"""
import os
import subprocess
import sys

from google.protobuf import descriptor_pb2
from google.protobuf.compiler import plugin_pb2

KEYWORDS = {
    # C99 keywords, plus the names <stdbool.h> defines as macros.
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
    "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict",
    "return", "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union",
    "unsigned", "void", "volatile", "while", "bool", "true", "false",
    # C++ keywords, because the generated headers are also included from C++.
    "alignas", "alignof", "and", "asm", "catch", "class", "constexpr", "decltype", "delete",
    "explicit", "export", "friend", "mutable", "namespace", "new", "noexcept", "not", "nullptr",
    "operator", "or", "private", "protected", "public", "template", "this", "throw", "try",
    "typeid", "typename", "using", "virtual", "xor",
}

NANOPB_PLUGIN = os.environ.get("UBII_NANOPB_PLUGIN", "/usr/bin/protoc-gen-nanopb")
SCHEMA_SPEC = os.environ.get("UBII_SCHEMA_SPEC", "")
RECORD_FILE = "ubii/topicData/topicDataRecord.proto"
RECORD_MESSAGE = "ubii.topicData.TopicDataRecord"
RECORD_TYPES_HEADER = "ubii/record_types.h"


class SchemaError(Exception):
    pass


def read_keep_lines(path):
    """{message full name: set of field names} from the spec's `keep` lines (they accumulate)."""
    keep = {}
    with open(path, encoding="utf-8") as spec:
        for line in spec:
            words = line.split("#", 1)[0].split()
            if len(words) >= 2 and words[0] == "keep":
                keep.setdefault(words[1], set()).update(words[2:])
    return keep


def walk_messages(prefix, messages):
    for message in messages:
        name = prefix + "." + message.name
        yield name, message
        yield from walk_messages(name, message.nested_type)


def reduce_file(proto_file, keep):
    for name, message in walk_messages(proto_file.package, proto_file.message_type):
        if name not in keep:
            continue
        wanted = keep.pop(name)
        missing = wanted - {field.name for field in message.field}
        if missing:
            raise SchemaError("%s has no field %s" % (name, ", ".join(sorted(missing))))
        kept = [field for field in message.field if field.name in wanted]
        del message.field[:]
        message.field.extend(kept)


def type_owners(proto_files):
    """{'.package.Type': file name} for every message and enum, nested ones included."""
    owners = {}

    def add(prefix, messages, enums, file_name):
        for enum in enums:
            owners["." + prefix + "." + enum.name] = file_name
        for message in messages:
            name = prefix + "." + message.name
            owners["." + name] = file_name
            add(name, message.nested_type, message.enum_type, file_name)

    for proto_file in proto_files:
        add(proto_file.package, proto_file.message_type, proto_file.enum_type, proto_file.name)
    return owners


def prune_imports(proto_file, owners, generated):
    if proto_file.public_dependency or proto_file.weak_dependency:
        raise SchemaError("%s: public or weak imports are not supported" % proto_file.name)
    used = set()
    for name, message in walk_messages(proto_file.package, proto_file.message_type):
        for field in message.field:
            if field.type_name:
                owner = owners[field.type_name]
                if owner != proto_file.name and owner not in generated:
                    raise SchemaError("%s.%s needs %s, which the schema leaves out" %
                                      (name, field.name, owner))
                used.add(owner)
    kept = [dependency for dependency in proto_file.dependency if dependency in used]
    del proto_file.dependency[:]
    proto_file.dependency.extend(kept)


def rename_message(message):
    for field in message.field:
        if field.name in KEYWORDS:
            field.name += "_"
    for oneof in message.oneof_decl:
        if oneof.name in KEYWORDS:
            oneof.name += "_"
    for nested in message.nested_type:
        rename_message(nested)


def record_types_header(proto_file, schema):
    record = next(m for n, m in walk_messages(proto_file.package, proto_file.message_type)
                  if n == RECORD_MESSAGE)
    oneof = [i for i, decl in enumerate(record.oneof_decl) if decl.name == "type"][0]
    fields = sorted((field for field in record.field
                     if field.HasField("oneof_index") and field.oneof_index == oneof),
                    key=lambda field: field.number)
    lines = [
        "/* Generated by proto/nanopb_plugin.py for the %s schema: the TopicDataRecord value" % schema,
        " * members it has, in field number order.",
        " *   UBII_RECORD_TYPE_LIST: X(NAME, field number). NAME is the .proto member name in capitals;",
        " *     ubii/topic.h makes UBII_RECORD_NAME of each.",
        " *   UBII_RECORD_MEMBER_LIST: X(NAME, field number, \"member\", \"message format\", C++ type):",
        " *     the .proto member name, the type as ProcessingModule specs name it (\"double\",",
        " *     \"ubii.dataStructure.Vector3\"), and the type the C++ layer holds it in. */",
        "#ifndef UBII_RECORD_TYPES_H",
        "#define UBII_RECORD_TYPES_H",
        "",
        '#define UBII_SCHEMA_NAME "%s"' % schema,
        "",
        "#define UBII_RECORD_TYPE_LIST(X) \\",
    ]
    lines += ["    X(%s, %d) \\" % (field.name.upper(), field.number) for field in fields]
    lines += ["", "#define UBII_RECORD_MEMBER_LIST(X) \\"]
    lines += ['    X(%s, %d, "%s", "%s", %s) \\' % ((field.name.upper(), field.number, field.name) +
                                                  member_format(field)) for field in fields]
    lines += ["", "#endif", ""]
    return "\n".join(lines)


# Scalar members by descriptor type: the message format upstream's specs use, and the C++ type.
SCALAR_FORMATS = {
    descriptor_pb2.FieldDescriptorProto.TYPE_DOUBLE: ("double", "double"),
    descriptor_pb2.FieldDescriptorProto.TYPE_FLOAT: ("float", "float"),
    descriptor_pb2.FieldDescriptorProto.TYPE_INT32: ("int32", "::std::int32_t"),
    descriptor_pb2.FieldDescriptorProto.TYPE_BOOL: ("bool", "bool"),
    descriptor_pb2.FieldDescriptorProto.TYPE_STRING: ("string", "::std::string"),
}


def member_format(field):
    if field.type == descriptor_pb2.FieldDescriptorProto.TYPE_MESSAGE:
        name = field.type_name.lstrip(".")
        return (name, "::" + name.replace(".", "::"))
    if field.type not in SCALAR_FORMATS:
        raise SchemaError("TopicDataRecord.%s has a type the record API does not know" % field.name)
    return SCALAR_FORMATS[field.type]


def main():
    request = plugin_pb2.CodeGeneratorRequest.FromString(sys.stdin.buffer.read())
    generated = set(request.file_to_generate)
    schema = os.path.splitext(os.path.basename(SCHEMA_SPEC))[0] or "full"
    keep = read_keep_lines(SCHEMA_SPEC) if SCHEMA_SPEC else {}
    to_generate = [f for f in request.proto_file if f.name in generated]
    try:
        for proto_file in to_generate:
            reduce_file(proto_file, keep)
        if keep:
            raise SchemaError("keep lines for messages not generated: " + ", ".join(sorted(keep)))
        owners = type_owners(request.proto_file)
        for proto_file in to_generate:
            prune_imports(proto_file, owners, generated)
    except SchemaError as error:
        sys.stderr.write("%s: %s\n" % (SCHEMA_SPEC or "schema", error))
        return 1
    record_header = None
    for proto_file in to_generate:
        if proto_file.name == RECORD_FILE:
            # Before the rename: the names in capitals are upstream's (DOUBLE, not DOUBLE_).
            record_header = record_types_header(proto_file, schema)
        for message in proto_file.message_type:
            rename_message(message)
    result = subprocess.run([NANOPB_PLUGIN], input=request.SerializeToString(), stdout=subprocess.PIPE)
    if result.returncode != 0 or record_header is None:
        sys.stdout.buffer.write(result.stdout)
        return result.returncode
    response = plugin_pb2.CodeGeneratorResponse.FromString(result.stdout)
    header = response.file.add()
    header.name = RECORD_TYPES_HEADER
    header.content = record_header
    sys.stdout.buffer.write(response.SerializeToString())
    return 0


if __name__ == "__main__":
    sys.exit(main())
