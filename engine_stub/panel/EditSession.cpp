#include "panel/EditSession.h"

#include <cstdio>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "textio/SafeFile.h"
#include "panel/YamlTextEdit.h"

namespace cube::panel {

namespace {

constexpr size_t kMaxFileBytes = 4u << 20;  // the plugin's limit for a reaction file

bool readText(const std::string& path, std::string* text, std::string* error) {
    textio::FileError code = textio::FileError::None;
    std::string why;
    if (textio::readFileBounded(path, kMaxFileBytes, text, &code, &why)) return true;
    *error = path + ": cannot read: " + why;
    return false;
}

struct Segment {
    std::string name;  ///< a key, or empty for an index
    size_t index = 0;
};

bool splitKey(const std::string& key, std::vector<Segment>* out, std::string* error) {
    out->clear();
    size_t i = 0;
    while (i < key.size()) {
        const size_t stop = key.find_first_of(".[", i);
        const std::string name = key.substr(i, stop == std::string::npos ? std::string::npos : stop - i);
        if (!name.empty()) out->push_back({name, 0});
        if (stop == std::string::npos) break;
        i = stop + 1;
        if (key[stop] == '[') {
            const size_t close = key.find(']', i);
            if (close == std::string::npos || close == i) {
                *error = "key '" + key + "': expected [index]";
                return false;
            }
            size_t index = 0;
            for (size_t k = i; k < close; ++k) {
                if (key[k] < '0' || key[k] > '9' || index > 100000) {
                    *error = "key '" + key + "': expected a number in [index]";
                    return false;
                }
                index = index * 10 + size_t(key[k] - '0');
            }
            out->push_back({"", index});
            i = close + 1;
            if (i < key.size() && key[i] == '.') ++i;
        }
    }
    if (out->empty()) *error = "empty key";
    return !out->empty();
}

// The map of the reaction named `name` in the document's `reactions` list.
bool findReaction(const YAML::Node& root, const std::string& name, YAML::Node* out) {
    const YAML::Node list = root["reactions"];
    if (!list || !list.IsSequence()) return false;
    for (const YAML::Node& r : list) {
        if (r.IsMap() && r["name"] && r["name"].IsScalar() && r["name"].Scalar() == name) {
            *out = r;
            return true;
        }
    }
    return false;
}

// Adds `key: value` to map `map` (block or flow) in the text.
bool addToMap(std::string* text, const YAML::Node& map, const std::string& key, const std::string& value,
              std::string* error) {
    if (map.Style() != YAML::EmitterStyle::Flow) return appendToBlockMap(text, map, key, value, error);
    TextSpan span;
    if (!flowSpan(*text, map, &span, error)) return false;
    const std::string entry = (map.size() > 0 ? ", " : "") + key + ": " + value;
    text->insert(span.end - 1, entry);
    return true;
}

// Follows `path` down from `from`; returns how many segments were found. `nodes` gets `from` and
// each node found (kept in a list: assigning a YAML::Node would write through it).
size_t walk(const YAML::Node& from, const std::vector<Segment>& path, std::vector<YAML::Node>* nodes) {
    nodes->assign(1, from);
    size_t found = 0;
    for (const Segment& s : path) {
        const YAML::Node& at = nodes->back();
        if (!s.name.empty()) {
            if (!at.IsMap() || !at[s.name]) break;
            nodes->push_back(at[s.name]);
        } else {
            if (!at.IsSequence() || s.index >= at.size()) break;
            nodes->push_back(at[s.index]);
        }
        ++found;
    }
    return found;
}

}  // namespace

bool EditSession::hasEntry(int reaction, const std::string& key) const {
    int doc = -1;
    std::string error;
    std::vector<Segment> path;
    if (!locate(reaction, &doc, &error) || !splitKey(key, &path, &error)) return false;
    try {
        YAML::Node reactionMap;
        if (!findReaction(YAML::Load(docs_[size_t(doc)].text), plugin_.reactionName(reaction), &reactionMap)) return false;
        std::vector<YAML::Node> nodes;
        return walk(reactionMap, path, &nodes) == path.size();
    } catch (const YAML::Exception&) {
        return false;
    }
}

bool EditSession::open(std::string* error) {
    docs_.clear();
    undo_.clear();
    redo_.clear();
    for (const std::string& path : plugin_.reactionFiles()) {
        Document d;
        d.path = path;
        if (!readText(path, &d.text, error)) return false;
        d.savedText = d.text;
        docs_.push_back(std::move(d));
    }
    return true;
}

int EditSession::documentOf(int reaction) const {
    const std::string file = plugin_.reactionFile(reaction);
    for (size_t i = 0; i < docs_.size(); ++i) {
        if (!file.empty() && docs_[i].path == file) return int(i);
    }
    return -1;
}

bool EditSession::locate(int reaction, int* doc, std::string* error) const {
    *doc = reaction >= 0 && reaction < plugin_.reactionCount() ? documentOf(reaction) : -1;
    if (*doc < 0) {
        *error = "reaction " + std::to_string(reaction) + " is not in an open file";
        return false;
    }
    return true;
}

bool EditSession::apply(int doc, const std::string& text, const std::string& group, bool record, std::string* error) {
    Document& d = docs_[size_t(doc)];
    if (text == d.text) return true;
    fx::Diagnostics diags;
    if (!plugin_.loadReactionsFromText(d.path, text, &diags)) {
        *error = diags.empty() ? d.path + ": refused" : diags.front().str();
        return false;
    }
    if (record) {
        const bool merge = groupOpen_ && !group.empty() && !undo_.empty() && undo_.back().group == group &&
                           undo_.back().doc == doc;
        if (merge) {
            undo_.back().after = text;
        } else {
            undo_.push_back({doc, d.text, text, group});
        }
        groupOpen_ = !group.empty();
        redo_.clear();
    }
    d.text = text;
    ++version_;
    return true;
}

template <class Edit>
bool EditSession::editReaction(int reaction, int doc, std::string* text, const Edit& edit, std::string* error) const {
    *text = docs_[size_t(doc)].text;
    try {
        const YAML::Node root = YAML::Load(*text);
        YAML::Node reactionMap;
        if (!findReaction(root, plugin_.reactionName(reaction), &reactionMap)) {
            *error = docs_[size_t(doc)].path + ": no reaction named '" + plugin_.reactionName(reaction) + "'";
            return false;
        }
        return edit(reactionMap, text);
    } catch (const YAML::Exception& e) {
        *error = docs_[size_t(doc)].path + ": " + e.what();
        return false;
    }
}

bool EditSession::set(int reaction, const std::string& key, const std::string& value, std::string* error,
                      const std::string& group) {
    int doc = -1;
    if (!locate(reaction, &doc, error)) return false;
    std::vector<Segment> path;
    if (!splitKey(key, &path, error)) return false;
    std::string text;
    const bool edited = editReaction(reaction, doc, &text, [&](const YAML::Node& reactionMap, std::string* fileText) {
        std::vector<YAML::Node> nodes;
        const size_t found = walk(reactionMap, path, &nodes);
        if (found == path.size()) {
            const YAML::Node& target = nodes.back();
            if (target.IsScalar()) return replaceScalar(fileText, target, value, error);
            TextSpan span;
            if (!valueSpan(*fileText, target, &span, error)) return false;
            *fileText = replaced(*fileText, span, value);
            return true;
        }
        if (found + 1 == path.size() && !path.back().name.empty() && nodes.back().IsMap())
            return addToMap(fileText, nodes.back(), path.back().name, value, error);
        if (found + 2 == path.size() && found == 0 && !path.back().name.empty()) {
            // The whole section is absent: add it as a one-line flow map.
            return addToMap(fileText, reactionMap, path[0].name, "{" + path[1].name + ": " + value + "}", error);
        }
        *error = "'" + key + "' cannot be set: the file has no such entry to edit";
        return false;
    }, error);
    if (!edited) return false;
    return apply(doc, text, group.empty() ? std::string() : std::to_string(reaction) + "/" + group, true, error);
}

bool EditSession::editStopLine(int reaction, int stop, bool duplicate, std::string* error) {
    int doc = -1;
    if (!locate(reaction, &doc, error)) return false;
    std::string text;
    const bool edited = editReaction(reaction, doc, &text, [&](const YAML::Node& reactionMap, std::string* fileText) {
        const YAML::Node ramp = reactionMap["particle"] ? reactionMap["particle"]["colour_ramp"] : YAML::Node();
        if (!ramp || !ramp.IsSequence() || stop < 0 || size_t(stop) >= ramp.size()) {
            *error = "the file has no colour_ramp stop " + std::to_string(stop) + " to " +
                     (duplicate ? "copy" : "remove");
            return false;
        }
        TextSpan line;
        if (!sequenceItemLine(*fileText, ramp[size_t(stop)], &line, error)) return false;
        if (duplicate) {
            fileText->insert(line.end, fileText->substr(line.begin, line.end - line.begin));
        } else {
            fileText->erase(line.begin, line.end - line.begin);
        }
        return true;
    }, error);
    if (!edited) return false;
    groupOpen_ = false;
    return apply(doc, text, "", true, error);
}

bool EditSession::replay(std::vector<Step>* from, std::vector<Step>* to, std::string Step::*text,
                         std::string* error) {
    if (from->empty()) return false;
    Step s = from->back();
    if (!apply(s.doc, s.*text, "", false, error)) return false;
    from->pop_back();
    to->push_back(s);
    groupOpen_ = false;
    return true;
}

bool EditSession::undo(std::string* error) { return replay(&undo_, &redo_, &Step::before, error); }

bool EditSession::redo(std::string* error) { return replay(&redo_, &undo_, &Step::after, error); }

bool EditSession::save(int doc, std::string* error) {
    Document& d = docs_[size_t(doc)];
    const std::string tmp = d.path + ".saving";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << d.text;
        out.close();
        if (!out) {
            std::remove(tmp.c_str());
            *error = d.path + ": cannot write " + tmp + " (folder not writable?)";
            return false;
        }
    }
    if (std::rename(tmp.c_str(), d.path.c_str()) != 0) {
        std::remove(tmp.c_str());
        *error = d.path + ": cannot replace the file with the saved text";
        return false;
    }
    d.savedText = d.text;
    d.conflict = false;
    return true;
}

bool EditSession::revert(int doc, std::string* error) {
    Document& d = docs_[size_t(doc)];
    std::string disk;
    if (!readText(d.path, &disk, error)) return false;
    groupOpen_ = false;
    if (!apply(doc, disk, "", true, error)) return false;
    d.savedText = disk;
    d.conflict = false;
    return true;
}

bool EditSession::checkDisk(std::string* error) {
    bool ask = false;
    for (size_t i = 0; i < docs_.size(); ++i) {
        Document& d = docs_[i];
        std::string disk;
        if (!readText(d.path, &disk, error)) continue;  // gone for now: keep what runs
        if (disk == d.savedText) {
            ask = ask || d.conflict;
            continue;
        }
        if (!d.dirty()) {
            d.savedText = disk;
            groupOpen_ = false;
            apply(int(i), disk, "", true, error);  // a bad file on disk: the error says so, the set stays
            continue;
        }
        d.conflict = true;
        d.diskText = disk;
        ask = true;
    }
    return ask;
}

bool EditSession::resolveConflict(int doc, bool reloadFromDisk, std::string* error) {
    Document& d = docs_[size_t(doc)];
    if (!d.conflict) return true;
    d.conflict = false;
    d.savedText = d.diskText;
    if (!reloadFromDisk) return true;
    groupOpen_ = false;
    return apply(doc, d.diskText, "", true, error);
}

}  // namespace cube::panel
