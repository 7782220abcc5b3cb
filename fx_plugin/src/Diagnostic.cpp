#include "fx/Diagnostic.h"

namespace fx {

const char* errorCodeName(ErrorCode code) {
    switch (code) {
    case ErrorCode::None: return "None";
    case ErrorCode::FileNotFound: return "FileNotFound";
    case ErrorCode::EmptyFile: return "EmptyFile";
    case ErrorCode::SyntaxError: return "SyntaxError";
    case ErrorCode::TooDeep: return "TooDeep";
    case ErrorCode::WrongType: return "WrongType";
    case ErrorCode::UnknownKey: return "UnknownKey";
    case ErrorCode::MissingKey: return "MissingKey";
    case ErrorCode::OutOfRange: return "OutOfRange";
    case ErrorCode::NotFinite: return "NotFinite";
    case ErrorCode::NegativeCount: return "NegativeCount";
    case ErrorCode::InvalidEnum: return "InvalidEnum";
    case ErrorCode::DuplicateName: return "DuplicateName";
    case ErrorCode::DuplicateKey: return "DuplicateKey";
    case ErrorCode::FileTooLarge: return "FileTooLarge";
    case ErrorCode::TooManyErrors: return "TooManyErrors";
    case ErrorCode::VersionMismatch: return "VersionMismatch";
    case ErrorCode::NullArgument: return "NullArgument";
    case ErrorCode::IndexOutOfRange: return "IndexOutOfRange";
    case ErrorCode::InvalidValue: return "InvalidValue";
    case ErrorCode::InvalidView: return "InvalidView";
    case ErrorCode::SizeMismatch: return "SizeMismatch";
    case ErrorCode::NoGlContext: return "NoGlContext";
    case ErrorCode::ShaderBuild: return "ShaderBuild";
    case ErrorCode::ResourceMissing: return "ResourceMissing";
    }
    return "Unknown";
}

std::string Diagnostic::str() const {
    // "file:line:col: error[Code] key: message"; unknown line/column are left out rather than
    // printed as 0 so editors that jump to file:line do not land on a line that does not exist.
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

}  // namespace fx
