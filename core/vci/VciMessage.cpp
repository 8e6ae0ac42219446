#include "VciMessage.h"

namespace sortie::vci {

std::string_view toString(VciErrorCode code)
{
    switch (code) {
    case VciErrorCode::BadStartLine: return "bad start line";
    case VciErrorCode::UnsupportedVersion: return "unsupported version";
    case VciErrorCode::UnknownVerb: return "unknown verb";
    case VciErrorCode::BadUri: return "bad URI";
    case VciErrorCode::BadHeader: return "bad header";
    case VciErrorCode::LineTooLong: return "line too long";
    case VciErrorCode::TooManyHeaders: return "too many headers";
    case VciErrorCode::MissingEmptyLine: return "missing empty line";
    case VciErrorCode::BadContentLength: return "bad Content-Length";
    case VciErrorCode::BodyTooLarge: return "body too large";
    case VciErrorCode::BadJson: return "bad JSON";
    }
    return "unknown error";
}

int VciParseError::replyStatus() const
{
    if (kindKnown && kind == VciMessageKind::Response)
        return 0;
    if (verb == "NOTIFY")
        return 0; // a NOTIFY is never answered, not even when it is broken
    return code == VciErrorCode::UnknownVerb ? 501 : 400;
}

} // namespace sortie::vci
