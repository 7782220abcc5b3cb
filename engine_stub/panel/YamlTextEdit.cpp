#include "panel/YamlTextEdit.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace cube::panel {

namespace {

std::string where(const YAML::Node& node) {
    const YAML::Mark m = node.Mark();
    return "line " + std::to_string(m.line + 1) + ", column " + std::to_string(m.column + 1);
}

bool startOf(const std::string& text, const YAML::Node& node, size_t* pos, std::string* error) {
    const int p = node.Mark().pos;
    if (p < 0 || size_t(p) >= text.size()) {
        *error = "the value has no position in the text (not parsed from it)";
        return false;
    }
    *pos = size_t(p);
    return true;
}

// From an opening quote at `pos`, the position after the closing one (npos when unclosed or
// the string spans lines, which an in-place edit does not handle).
size_t quotedEnd(const std::string& text, size_t pos) {
    const char q = text[pos];
    for (size_t i = pos + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') return std::string::npos;
        if (q == '"' && c == '\\') {
            ++i;
            continue;
        }
        if (c == q) {
            if (q == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {  // '' is an escaped quote
                ++i;
                continue;
            }
            return i + 1;
        }
    }
    return std::string::npos;
}

}  // namespace

bool scalarSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error) {
    if (!node.IsScalar()) {
        *error = where(node) + ": expected a scalar value";
        return false;
    }
    size_t pos = 0;
    if (!startOf(text, node, &pos, error)) return false;
    if (text[pos] == '"' || text[pos] == '\'') {
        const size_t end = quotedEnd(text, pos);
        if (end == std::string::npos) {
            *error = where(node) + ": expected a quoted value closed on the same line";
            return false;
        }
        *span = {pos, end};
        return true;
    }
    const std::string& s = node.Scalar();
    if (s.empty() || text.compare(pos, s.size(), s) != 0) {
        // A plain scalar's text is its value unless it was folded over several lines.
        *error = where(node) + ": expected a one-line plain value, found text that differs from it";
        return false;
    }
    *span = {pos, pos + s.size()};
    return true;
}

bool flowSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error) {
    size_t pos = 0;
    if (!startOf(text, node, &pos, error)) return false;
    if (text[pos] != '[' && text[pos] != '{') {
        *error = where(node) + ": expected a flow collection ([...] or {...})";
        return false;
    }
    int depth = 0;
    for (size_t i = pos; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"' || c == '\'') {
            const size_t end = quotedEnd(text, i);
            if (end == std::string::npos) break;
            i = end - 1;
        } else if (c == '#' && i > 0 && (text[i - 1] == ' ' || text[i - 1] == '\t')) {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            if (--depth == 0) {
                *span = {pos, i + 1};
                return true;
            }
        }
    }
    *error = where(node) + ": expected the flow collection to be closed";
    return false;
}

bool valueSpan(const std::string& text, const YAML::Node& node, TextSpan* span, std::string* error) {
    if (node.IsScalar()) return scalarSpan(text, node, span, error);
    if ((node.IsSequence() || node.IsMap()) && node.Style() == YAML::EmitterStyle::Flow) {
        return flowSpan(text, node, span, error);
    }
    *error = where(node) + ": expected a scalar or a flow collection, found a block collection";
    return false;
}

std::string replaced(const std::string& text, TextSpan span, const std::string& with) {
    return text.substr(0, span.begin) + with + text.substr(span.end);
}

bool replaceScalar(std::string* text, const YAML::Node& node, const std::string& value, std::string* error) {
    TextSpan span;
    if (!scalarSpan(*text, node, &span, error)) return false;
    const char first = (*text)[span.begin];
    std::string out = value;
    if (first == '\'') {
        out = "'";
        for (char c : value) out += c == '\'' ? std::string("''") : std::string(1, c);
        out += "'";
    } else if (first == '"') {
        out = "\"";
        for (char c : value) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
        out += "\"";
    }
    *text = replaced(*text, span, out);
    return true;
}

bool appendToBlockMap(std::string* text, const YAML::Node& map, const std::string& key,
                      const std::string& value, std::string* error) {
    if (!map.IsMap() || map.Style() == YAML::EmitterStyle::Flow || map.size() == 0) {
        *error = where(map) + ": expected a block map with at least one key to add '" + key + "' to";
        return false;
    }
    // The keys' column, and the line of the last key.
    int column = -1, lastLine = -1;
    for (auto it = map.begin(); it != map.end(); ++it) {
        const YAML::Mark m = it->first.Mark();
        if (column < 0) column = m.column;
        lastLine = std::max(lastLine, m.line);
    }
    // Lines are 0-based; walk to the first line after lastLine that is not blank, not a comment
    // and indented no deeper than the keys: the map ends before it.
    size_t pos = 0;
    for (int line = 0; line <= lastLine && pos != std::string::npos; ++line) {
        pos = line == 0 ? 0 : text->find('\n', pos);
        if (line > 0 && pos != std::string::npos) ++pos;
    }
    if (pos == std::string::npos) {
        *error = where(map) + ": the map's last key is past the end of the text";
        return false;
    }
    size_t insertAt = text->find('\n', pos);
    insertAt = insertAt == std::string::npos ? text->size() : insertAt + 1;
    for (size_t p = insertAt; p < text->size();) {
        size_t eol = text->find('\n', p);
        if (eol == std::string::npos) eol = text->size();
        const size_t firstChar = text->find_first_not_of(" \t", p);
        const bool blank = firstChar == std::string::npos || firstChar >= eol;
        const bool comment = !blank && (*text)[firstChar] == '#';
        if (!blank && !comment) {
            if (int(firstChar - p) <= column) break;
            insertAt = eol < text->size() ? eol + 1 : text->size();
        }
        p = eol + 1;
    }
    std::string line = std::string(size_t(column), ' ') + key + ": " + value + "\n";
    if (insertAt > 0 && (*text)[insertAt - 1] != '\n') line = "\n" + line;
    text->insert(insertAt, line);
    return true;
}

bool sequenceItemLine(const std::string& text, const YAML::Node& item, TextSpan* span, std::string* error) {
    TextSpan value;
    if (!valueSpan(text, item, &value, error)) return false;
    const size_t lineStart = text.rfind('\n', value.begin) == std::string::npos ? 0 : text.rfind('\n', value.begin) + 1;
    const size_t dash = text.find_first_not_of(" \t", lineStart);
    const bool ownLine = dash != std::string::npos && text[dash] == '-' &&
                         text.find_first_not_of(" \t", dash + 1) == value.begin &&
                         text.find('\n', lineStart) >= value.end;
    if (!ownLine) {
        *error = where(item) + ": expected a list entry on a line of its own (\"- value\")";
        return false;
    }
    size_t lineEnd = text.find('\n', value.end);
    lineEnd = lineEnd == std::string::npos ? text.size() : lineEnd + 1;
    *span = {lineStart, lineEnd};
    return true;
}

std::string formatNumber(double value, bool integer, const std::string& likeText) {
    if (integer) return std::to_string(static_cast<long long>(std::llround(value)));
    char buf[48];
    auto r = std::to_chars(buf, buf + sizeof buf, static_cast<float>(value));
    std::string s(buf, r.ptr);
    if (s == "-0") s = "0";
    const bool wantsPoint = likeText.find('.') != std::string::npos;
    if (wantsPoint && s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

}  // namespace cube::panel
