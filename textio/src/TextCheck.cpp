#include "textio/TextCheck.h"

namespace textio {

bool isYamlText(const std::string& text, NonTextByte* where) {
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const size_t n = text.size();
    int line = 0, column = 0;
    size_t i = (n >= 3 && s[0] == 0xEF && s[1] == 0xBB && s[2] == 0xBF) ? 3 : 0;  // UTF-8 BOM
    while (i < n) {
        const unsigned char c = s[i];
        size_t len = 0;
        bool ok = true;
        if (c < 0x80) {
            len = 1;
            ok = (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') && c != 0x7F;
        } else if (c >= 0xC2 && c <= 0xDF) {
            len = 2;
        } else if (c >= 0xE0 && c <= 0xEF) {
            len = 3;
        } else if (c >= 0xF0 && c <= 0xF4) {
            len = 4;
        } else {
            ok = false;
        }
        if (ok && len > 1) {
            ok = i + len <= n;
            for (size_t k = 1; ok && k < len; ++k) ok = (s[i + k] & 0xC0) == 0x80;
            if (ok && len == 3) {
                ok = !(c == 0xE0 && s[i + 1] < 0xA0) && !(c == 0xED && s[i + 1] >= 0xA0);
            } else if (ok && len == 4) {
                ok = !(c == 0xF0 && s[i + 1] < 0x90) && !(c == 0xF4 && s[i + 1] >= 0x90);
            }
        }
        if (!ok) {
            if (where) *where = NonTextByte{line, column, c};
            return false;
        }
        if (c == '\n') {
            ++line;
            column = 0;
        } else {
            ++column;
        }
        i += len;
    }
    return true;
}

}  // namespace textio
