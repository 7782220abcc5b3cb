#pragma once
// Is this YAML text? The reaction loader and the engine's legacy smoke loader both refuse a file
// with control bytes or malformed UTF-8 before the YAML parser sees it, and name the first
// offending byte.
#include <cstddef>
#include <cstdio>
#include <string>

namespace textio {

/// Where the first byte that is not UTF-8 text is (0-based line and column, columns counting
/// characters), and a message for it.
struct NonTextByte {
    int line = 0;
    int column = 0;
    unsigned char byte = 0;
    std::string message() const {
        char buf[8];
        std::snprintf(buf, sizeof buf, "0x%02X", byte);
        return std::string("binary data: byte ") + buf + " cannot appear in a YAML text file (expected UTF-8 text)";
    }
};

/// False, with the first offending byte in *where, when `text` holds a control byte other than
/// tab/CR/LF, DEL, or malformed or overlong UTF-8 (a leading UTF-8 BOM is allowed).
bool isYamlText(const std::string& text, NonTextByte* where);

}  // namespace textio
