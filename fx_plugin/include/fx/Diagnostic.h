#pragma once
// Errors found in data (reaction files). Each rule has its own code so tests assert the code,
// not the wording; the message says where and what was expected.
#include <string>
#include <vector>

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
};

const char* errorCodeName(ErrorCode code);

struct Diagnostic {
    ErrorCode code = ErrorCode::None;
    std::string file;
    int line = 0;     ///< 1-based; 0 when unknown
    int column = 0;   ///< 1-based; 0 when unknown
    std::string key;  ///< dotted path of the offending key, e.g. "reactions[0].particle.drag"
    std::string message;
    /// "file:line:col: error[Code] key: message"
    std::string str() const;
};

using Diagnostics = std::vector<Diagnostic>;

}  // namespace fx
