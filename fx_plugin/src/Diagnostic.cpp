#include "fx/Diagnostic.h"

// The C boundary's one table of error names (fx/fx.h); fx::errorCodeName and Diagnostic::str in
// the C++ layer read it.
extern "C" const char* fxErrorCodeName(int code) {
    using fx::ErrorCode;
    switch (static_cast<ErrorCode>(code)) {
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
    case ErrorCode::BadDescriptor: return "BadDescriptor";
    case ErrorCode::UnsupportedDepth: return "UnsupportedDepth";
    case ErrorCode::InvalidHandle: return "InvalidHandle";
    }
    return "Unknown";
}

static_assert(static_cast<int>(fx::ErrorCode::ResourceMissing) == FX_ERROR_RESOURCE_MISSING,
              "fx::ErrorCode and FX_ERROR_* must keep the same numbers");
static_assert(static_cast<int>(fx::ErrorCode::UnsupportedDepth) == FX_ERROR_UNSUPPORTED_DEPTH,
              "fx::ErrorCode and FX_ERROR_* must keep the same numbers");
static_assert(static_cast<int>(fx::ErrorCode::InvalidHandle) == FX_ERROR_INVALID_HANDLE &&
                  FX_ERROR_INVALID_HANDLE + 1 == FX_ERROR_COUNT_,
              "fx::ErrorCode and FX_ERROR_* must keep the same numbers");
