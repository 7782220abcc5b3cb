#pragma once
// Named errors. Two families share one enum: errors in data (reaction files), each rule with its
// own code so tests assert the code, not the wording, and the message says where and what was
// expected; and invalid calls of the API (an index out of range, a null pointer, a zero-size
// view ...), which are refused in every build type: the call has no effect, returns the code
// and the host's log gets "fx: error[Code] function: what was expected".
#include <string>
#include <vector>

#include "fx/Api.h"

namespace fx {

enum class ErrorCode {
    None = 0,
    FileNotFound,    ///< file or directory cannot be opened
    EmptyFile,       ///< nothing but whitespace/comments
    SyntaxError,     ///< YAML that does not parse (truncated, malformed, binary garbage)
    TooDeep,         ///< nesting deeper than any reaction needs
    WrongType,       ///< scalar where a map was expected, text where a number was expected ...
    UnknownKey,      ///< a key the schema does not have (typos are errors, not silently ignored)
    MissingKey,      ///< a required key is absent
    OutOfRange,      ///< a number outside its documented range
    NotFinite,       ///< NaN or Inf
    NegativeCount,   ///< a count (capacity, frames) below zero
    InvalidEnum,     ///< a word not in the key's list (type, technique, blend, surface)
    DuplicateName,   ///< two reactions with one name
    DuplicateKey,    ///< one key twice in the same map (YAML would silently keep one)
    FileTooLarge,    ///< a file or text past the loader's size limit (read nothing of it)
    TooManyErrors,   ///< the per-file diagnostic limit was reached; the rest were not listed

    // Invalid API calls (no effect; reported through the host's log and the return value).
    VersionMismatch, ///< PluginImports::apiVersion is not compatible with the plugin (see Api.h)
    NullArgument,    ///< a required pointer is null (PluginImports::host)
    IndexOutOfRange, ///< a reaction index outside 0 .. reactionCount() - 1
    InvalidValue,    ///< a non-finite or negative time step, an enum value the API does not have
    InvalidView,     ///< zero or negative view size, near/far planes not 0 < near < far, non-finite matrices
    SizeMismatch,    ///< sceneColor / sceneDepth / ViewInfo disagree on the view's size
    NoGlContext,     ///< the host's getProcAddress gave no GL entry points (no context current?)
    ShaderBuild,     ///< a particle program failed to compile or link (message has file:line)
    ResourceMissing, ///< the smoke atlas or a shader could not be read (from an override folder)
    // API 2.0
    BadDescriptor,    ///< a C descriptor's size is one the library does not know (fx/fx.h)
    UnsupportedDepth, ///< a depth texture format or depth source the plugin cannot read
    InvalidHandle,    ///< a plugin handle that is not live (destroyed, or never created: fx/fx.h)
};

/// "FileNotFound", ... (the same numbers as fx/fx.h's FX_ERROR_*).
inline const char* errorCodeName(ErrorCode code) { return fxErrorCodeName(static_cast<int>(code)); }

struct Diagnostic {
    ErrorCode code = ErrorCode::None;
    std::string file;
    int line = 0;     ///< 1-based; 0 when unknown
    int column = 0;   ///< 1-based; 0 when unknown
    std::string key;  ///< dotted path of the offending key, e.g. "reactions[0].particle.drag"
    std::string message;
    /// "file:line:col: error[Code] key: message"; an unknown line or column is left out rather
    /// than printed as 0, so editors that jump to file:line do not land on a line that does not
    /// exist.
    std::string str() const {
        std::string s = file.empty() ? std::string("<text>") : file;
        if (line > 0) {
            s += ':' + std::to_string(line);
            if (column > 0) s += ':' + std::to_string(column);
        }
        s += ": error[";
        s += errorCodeName(code);
        s += "] ";
        if (!key.empty()) s += key + ": ";
        s += message;
        return s;
    }
};

using Diagnostics = std::vector<Diagnostic>;

}  // namespace fx
