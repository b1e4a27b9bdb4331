#!/usr/bin/python3
"""protoc plugin: nanopb's generator, with C/C++ keyword field names renamed first.

Upstream's TopicDataRecord has oneof members named `double`, `bool` and `float`. nanopb 0.4.7 emits
struct members with exactly those names, which is not valid C. This wrapper appends "_" to any field
or oneof name that is a C or C++ keyword (the rename protoc's own C++ generator applies) and then
hands the request to Debian's protoc-gen-nanopb unchanged otherwise.

Only the C identifiers change: field numbers and types, and therefore the bytes on the wire, are the
same, and the .proto files keep upstream's names (which are also the proto-JSON names).
"""
import os
import subprocess
import sys

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


def rename_message(message):
    for field in message.field:
        if field.name in KEYWORDS:
            field.name += "_"
    for oneof in message.oneof_decl:
        if oneof.name in KEYWORDS:
            oneof.name += "_"
    for nested in message.nested_type:
        rename_message(nested)


def main():
    request = plugin_pb2.CodeGeneratorRequest.FromString(sys.stdin.buffer.read())
    for proto_file in request.proto_file:
        for message in proto_file.message_type:
            rename_message(message)
    result = subprocess.run([NANOPB_PLUGIN], input=request.SerializeToString(), stdout=subprocess.PIPE)
    sys.stdout.buffer.write(result.stdout)
    return result.returncode


if __name__ == "__main__":
    sys.exit(main())
