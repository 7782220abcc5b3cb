#pragma once
// Loading reaction files (reactions/*.yaml) into a validated ReactionSet.
//
// Contract shared by every function here:
//  - every problem found is appended to `diags` (may be null) with its own ErrorCode, file,
//    1-based line/column and dotted key; a file is checked to the end, not to its first error
//    (up to kMaxDiagnosticsPerFile, then one TooManyErrors);
//  - on any error false is returned and `out` is left untouched; on success `*out` is replaced;
//  - no input makes them crash, hang, throw or allocate in proportion to a number in the file
//    (sizes are validated before anything is allocated; nesting is bounded; binary data is
//    rejected before it reaches the YAML parser). loadReactionText is the fuzzing entry point.
#include <string>
#include <vector>

#include "fx/Diagnostic.h"
#include "reactions/ReactionDesc.h"

namespace fx {

/// One file's bytes and the name its messages use.
struct ReactionSource {
    std::string name;
    std::string text;
};

/// Parses and validates one file's text. `nameForMessages` fills Diagnostic::file.
bool loadReactionText(const std::string& text, const std::string& nameForMessages,
                      ReactionSet* out, Diagnostics* diags);
/// Reads and loads one file (FileNotFound, FileTooLarge before any parsing).
bool loadReactionFile(const std::string& path, ReactionSet* out, Diagnostics* diags);
/// Every *.yaml in `dir` (not recursive), in sorted file-name order, as one set; errors from
/// every file are reported. A directory without a .yaml file is FileNotFound.
bool loadReactionDirectory(const std::string& dir, ReactionSet* out, Diagnostics* diags);
/// loadReactionDirectory when `path` is a directory, else loadReactionFile.
bool loadReactionPath(const std::string& path, ReactionSet* out, Diagnostics* diags);
/// Several already-read files as one set, in the given order: each is validated on its own,
/// then names must be unique and capacities must fit kMaxTotalCapacity across all of them.
bool loadReactionSources(const std::vector<ReactionSource>& sources, ReactionSet* out,
                         Diagnostics* diags);

/// Reads a whole regular file, refusing more than kMaxFileBytes, without blocking on a FIFO.
/// Reports FileNotFound (missing, not a regular file, symlink loop) / FileTooLarge.
bool readReactionFileText(const std::string& path, std::string* text, Diagnostics* diags);
/// The *.yaml entries directly in `dir`, sorted by file name, of any kind (a FIFO or a dangling
/// or looping symlink is listed so that reading it reports it). Reports FileNotFound when `dir`
/// cannot be listed; an empty result is not an error here.
bool listReactionFiles(const std::string& dir, std::vector<std::string>* files,
                       Diagnostics* diags);

}  // namespace fx
