#include "ReactionLoader.h"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <new>
#include <sstream>
#include <system_error>

#include <yaml-cpp/yaml.h>

#include "../base/TextIo.h"
#include "ReactionSchema.h"
#include "YamlCheck.h"

namespace fx {
namespace {

namespace fs = std::filesystem;

void add(Diagnostics* diags, ErrorCode code, const std::string& file, int line, int column,
         const std::string& key, const std::string& message) {
    if (diags) diags->push_back({code, file, line, column, key, message});
}

bool loadTextChecked(const std::string& text, YamlCheck& check, ReactionSet* set) {
    // Pass 1 (textio/YamlPreflight.h): size, text, syntax anywhere, one document at most.
    fxio::YamlProblem problem;
    bool hasDocument = false;
    if (!fxio::preflightYaml(text, kMaxFileBytes, kMaxNesting, &problem, &hasDocument)) {
        check.report(fxio::errorCodeAs<ErrorCode>(problem.code), problem.mark, "", problem.message);
        return false;
    }

    // Pass 2: the node tree of the one document.
    YAML::Node root;
    try {
        root = YAML::Load(text);
    } catch (const YAML::Exception& e) {  // pass 1 accepted it, so this is not expected
        check.report(ErrorCode::SyntaxError, e.mark, "", "malformed YAML: " + e.msg);
        return false;
    }
    if (!hasDocument || root.IsNull()) {
        check.report(ErrorCode::EmptyFile, !hasDocument ? fxio::yamlMarkAt(0, 0) : root.Mark(), "",
                     "the file holds no reactions; expected 'reactions:' with a list "
                     "('reactions: []' for none)");
        return false;
    }
    readReactionDocument(check, root, &set->reactions);
    return check.errors() == 0;
}

}  // namespace

bool loadReactionText(const std::string& text, const std::string& nameForMessages,
                      ReactionSet* out, Diagnostics* diags) {
    YamlCheck check(nameForMessages, diags);
    const size_t firstDiag = diags ? diags->size() : 0;
    ReactionSet set;
    bool ok = false;
    // Nothing may escape to the caller (the fuzzer, a hot reload in the middle of a frame):
    // yaml-cpp reports through exceptions, and allocation can fail.
    try {
        ok = loadTextChecked(text, check, &set);
    } catch (const std::bad_alloc&) {
        check.report(ErrorCode::FileTooLarge, YAML::Mark::null_mark(), "",
                     "out of memory while reading the file");
    } catch (const std::exception& e) {
        check.report(ErrorCode::SyntaxError, YAML::Mark::null_mark(), "",
                     std::string("unreadable YAML: ") + e.what());
    } catch (...) {
        check.report(ErrorCode::SyntaxError, YAML::Mark::null_mark(), "", "unreadable YAML");
    }
    if (!ok || check.errors() != 0) {
        // In file order (the schema reads keys in its own order), the overflow note last.
        if (diags) {
            std::stable_sort(diags->begin() + static_cast<std::ptrdiff_t>(firstDiag), diags->end(),
                             [](const Diagnostic& a, const Diagnostic& b) {
                                 auto rank = [](const Diagnostic& d) {
                                     return d.code == ErrorCode::TooManyErrors ? INT_MAX : d.line;
                                 };
                                 return rank(a) != rank(b) ? rank(a) < rank(b) : a.column < b.column;
                             });
        }
        return false;
    }
    set.files.push_back(nameForMessages);
    if (out) *out = std::move(set);
    return true;
}

bool readReactionFileText(const std::string& path, std::string* text, Diagnostics* diags) {
    // One opener for every loader (textio/SafeFile.h): regular files only, never blocks on a FIFO,
    // never reads past the limit.
    fxio::FileError code = fxio::FileError::None;
    std::string why;
    if (fxio::readFileBounded(path, kMaxFileBytes, text, &code, &why)) return true;
    if (code == fxio::FileError::TooLarge) {
        add(diags, ErrorCode::FileTooLarge, path, 0, 0, "", "file is " + why);
    } else {
        add(diags, ErrorCode::FileNotFound, path, 0, 0, "", "cannot open: " + why);
    }
    return false;
}

bool listReactionFiles(const std::string& dir, std::vector<std::string>* files,
                       Diagnostics* diags) {
    std::error_code ec;
    std::vector<std::string> found;
    fs::directory_iterator it(dir, ec), end;
    if (ec) {
        add(diags, ErrorCode::FileNotFound, dir, 0, 0, "", "cannot list directory: " + ec.message());
        return false;
    }
    // Every *.yaml entry is listed whatever it is (FIFO, symlink loop, folder): readReactionFileText
    // then reports each one by name instead of it vanishing from the set without a word.
    for (; it != end; it.increment(ec)) {
        if (ec) break;
        const fs::path& p = it->path();
        if (p.extension() == ".yaml") found.push_back(p.string());
    }
    if (ec) {
        add(diags, ErrorCode::FileNotFound, dir, 0, 0, "", "cannot list directory: " + ec.message());
        return false;
    }
    std::sort(found.begin(), found.end());
    *files = std::move(found);
    return true;
}

bool loadReactionSources(const std::vector<ReactionSource>& sources, ReactionSet* out,
                         Diagnostics* diags) {
    ReactionSet merged;
    bool ok = true;
    long long totalCapacity = 0;
    bool capacityReported = false;
    for (const ReactionSource& src : sources) {
        ReactionSet one;
        if (!loadReactionText(src.text, src.name, &one, diags)) {
            ok = false;
            continue;
        }
        for (size_t i = 0; i < one.reactions.size(); ++i) {
            const ReactionDesc& d = one.reactions[i];
            // The file's own key path (a layer's "reactions[0].layers[2]"): positions in the
            // merged set are not the file's.
            const std::string key = d.sourceKey.empty() ? "reactions[" + std::to_string(i) + "]" : d.sourceKey;
            for (const ReactionDesc& earlier : merged.reactions) {
                if (earlier.name == d.name) {
                    add(diags, ErrorCode::DuplicateName, d.sourceFile, d.sourceLine, 0,
                        key + ".name",
                        "reaction name '" + d.name + "' is already used at " +
                            earlier.sourceFile + ":" + std::to_string(earlier.sourceLine));
                    ok = false;
                    break;
                }
            }
            totalCapacity += d.emission.capacity;
            if (totalCapacity > kMaxTotalCapacity && !capacityReported) {
                add(diags, ErrorCode::OutOfRange, d.sourceFile, d.sourceLine, 0,
                    key + ".emission.capacity",
                    "the loaded reactions' capacities add up to more than " +
                        std::to_string(kMaxTotalCapacity) + " particles");
                capacityReported = true;
                ok = false;
            }
            merged.reactions.push_back(d);
        }
        merged.files.push_back(src.name);
    }
    if (!ok) return false;
    if (out) *out = std::move(merged);
    return true;
}

bool loadReactionFile(const std::string& path, ReactionSet* out, Diagnostics* diags) {
    std::string text;
    if (!readReactionFileText(path, &text, diags)) return false;
    return loadReactionText(text, path, out, diags);
}

bool loadReactionDirectory(const std::string& dir, ReactionSet* out, Diagnostics* diags) {
    std::vector<std::string> files;
    if (!listReactionFiles(dir, &files, diags)) return false;
    if (files.empty()) {
        add(diags, ErrorCode::FileNotFound, dir, 0, 0, "", "directory holds no *.yaml file");
        return false;
    }
    std::vector<ReactionSource> sources;
    bool ok = true;
    for (const std::string& f : files) {
        ReactionSource src;
        src.name = f;
        if (readReactionFileText(f, &src.text, diags)) {
            sources.push_back(std::move(src));
        } else {
            ok = false;
        }
    }
    // Validate what could be read even when a file could not, so every error is reported.
    ReactionSet set;
    ok = loadReactionSources(sources, &set, diags) && ok;
    if (!ok) return false;
    if (out) *out = std::move(set);
    return true;
}

bool loadReactionPath(const std::string& path, ReactionSet* out, Diagnostics* diags) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return loadReactionDirectory(path, out, diags);
    return loadReactionFile(path, out, diags);
}

}  // namespace fx
