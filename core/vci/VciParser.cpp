#include "VciParser.h"

#include "VciStartLine.h"

#include <algorithm>
#include <cstring>

namespace sortie::vci {
namespace {

constexpr size_t kCompactAt = 64 * 1024;

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
        s.remove_suffix(1);
    return s;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string shown(std::string_view s)
{
    constexpr size_t kShown = 60;
    std::string out = "\"";
    for (char c : s.substr(0, kShown)) {
        const auto u = static_cast<unsigned char>(c);
        out += (u >= 0x20 && u < 0x7f) ? c : '?';
    }
    out += s.size() > kShown ? "...\"" : "\"";
    return out;
}

// "application/json", "text/json", "json" or any "+json" type, parameters ignored.
bool isJsonMediaType(std::string_view value)
{
    std::string type(trim(value.substr(0, value.find(';'))));
    std::transform(type.begin(), type.end(), type.begin(), [](char c) { return c >= 'A' && c <= 'Z' ? char(c + 32) : c; });
    return type == "application/json" || type == "text/json" || type == "json"
        || (type.size() > 5 && type.compare(type.size() - 5, 5, "+json") == 0);
}

std::optional<uint64_t> parseLength(std::string_view s)
{
    if (s.empty() || s.size() > 19)
        return std::nullopt;
    uint64_t v = 0;
    for (char c : s) {
        if (c < '0' || c > '9')
            return std::nullopt;
        v = v * 10 + uint64_t(c - '0');
    }
    return v;
}

} // namespace

VciParser::VciParser(VciLimits limits)
    : m_limits(limits)
    , m_reader(limits.maxJsonDepth, limits.maxBodySize, limits.maxNumberLength, limits.maxDecodedBytes)
{
}

void VciParser::reset()
{
    m_buf.clear();
    m_pos = 0;
    m_offset = 0;
    m_state = State::StartLine;
    m_skipLine = false;
    m_result.reset();
    m_messages = m_errors = m_discarded = 0;
    m_reader.reset();
}

void VciParser::feed(std::string_view bytes)
{
    if (m_pos == m_buf.size()) {
        m_offset += m_pos;
        m_buf.clear();
        m_pos = 0;
    } else if (m_pos >= kCompactAt || (m_pos > 0 && m_pos * 2 > m_buf.size())) {
        m_buf.erase(0, m_pos);
        m_offset += m_pos;
        m_pos = 0;
    }
    m_buf.append(bytes.data(), bytes.size());
}

std::optional<VciParser::Result> VciParser::next()
{
    for (;;) {
        Step step = Step::NeedMore;
        switch (m_state) {
        case State::StartLine: step = onStartLine(); break;
        case State::Headers: step = onHeaderLine(); break;
        case State::BodyLength: step = onBodyLength(); break;
        case State::BodyJson: step = onBodyJson(); break;
        case State::Resync: step = onResync(); break;
        }
        if (step == Step::NeedMore)
            return std::nullopt;
        if (step == Step::Produced) {
            std::optional<Result> out = std::move(m_result);
            m_result.reset();
            return out;
        }
    }
}

// Discards the rest of a line that went over the limit. True when its end has been reached.
bool VciParser::skipLongLineRest(bool countDiscarded)
{
    const char *begin = m_buf.data() + m_pos;
    const void *lf = std::memchr(begin, '\n', m_buf.size() - m_pos);
    const size_t n = lf ? size_t(static_cast<const char *>(lf) - begin) + 1 : m_buf.size() - m_pos;
    m_pos += n;
    if (countDiscarded)
        m_discarded += n;
    if (lf)
        m_skipLine = false;
    return lf != nullptr;
}

VciParser::Line VciParser::takeLine(std::string_view *line, size_t *lineStart)
{
    const size_t available = m_buf.size() - m_pos;
    const size_t window = std::min(available, m_limits.maxLineLength);
    const char *begin = m_buf.data() + m_pos;
    const void *lf = std::memchr(begin, '\n', window);
    if (!lf) {
        if (available < m_limits.maxLineLength)
            return Line::NeedMore;
        // Drop the line: through its end when that is here, else all of it so far (never buffer more).
        *lineStart = m_pos;
        const void *end = std::memchr(begin + window, '\n', available - window);
        m_pos = end ? size_t(static_cast<const char *>(end) - m_buf.data()) + 1 : m_buf.size();
        m_skipLine = end == nullptr;
        return Line::TooLong;
    }
    size_t len = size_t(static_cast<const char *>(lf) - begin);
    *lineStart = m_pos;
    m_pos += len + 1;
    if (len > 0 && begin[len - 1] == '\r')
        --len;
    *line = std::string_view(begin, len);
    return Line::Ready;
}

void VciParser::beginMessage(uint64_t offset)
{
    m_msg = VciMessage{};
    m_msg.offset = offset;
    m_msg.headers.reserve(4);
    m_bad = false;
    m_msgKindKnown = false;
    m_verbText.clear();
    m_headerLines = 0;
    m_contentLength.reset();
    m_lengthBad = false;
    m_json = false;
    m_remaining = 0;
}

void VciParser::setError(VciErrorCode code, std::string message)
{
    if (m_bad)
        return; // the first problem is the one worth reporting
    m_bad = true;
    m_errCode = code;
    m_errMessage = std::move(message);
}

VciParser::Step VciParser::onStartLine()
{
    for (;;) {
        if (m_skipLine && !skipLongLineRest(false))
            return Step::NeedMore;
        std::string_view line;
        size_t start = 0;
        const Line got = takeLine(&line, &start);
        if (got == Line::NeedMore)
            return Step::NeedMore;
        if (got == Line::TooLong) {
            beginMessage(m_offset + start);
            setError(VciErrorCode::LineTooLong, "start line longer than " + std::to_string(m_limits.maxLineLength) + " bytes");
            m_state = State::Headers;
            return Step::Continue;
        }
        if (line.empty())
            continue; // empty lines between messages are tolerated
        beginMessage(m_offset + start);
        const VciStartLine sl = parseVciStartLine(line);
        m_msg.kind = sl.kind;
        m_verbText.assign(sl.verbText);
        if (sl.ok) {
            m_msg.verb = sl.verb;
            m_msg.uri.assign(sl.uri);
            m_msg.status = sl.status;
            m_msg.reason.assign(sl.reason);
        } else {
            m_msg.uri.assign(sl.uri);
            setError(sl.error, sl.message);
            m_msgKindKnown = sl.kindKnown;
        }
        if (sl.ok)
            m_msgKindKnown = true;
        m_state = State::Headers;
        return Step::Continue;
    }
}

VciParser::Step VciParser::onHeaderLine()
{
    if (m_skipLine && !skipLongLineRest(false))
        return Step::NeedMore;
    std::string_view line;
    size_t start = 0;
    const Line got = takeLine(&line, &start);
    if (got == Line::NeedMore)
        return Step::NeedMore;
    if (got == Line::TooLong) {
        setError(VciErrorCode::LineTooLong, "header line longer than " + std::to_string(m_limits.maxLineLength) + " bytes");
        return Step::Continue;
    }
    if (line.empty())
        return endOfHeaders();

    const size_t colon = line.find(':');
    const std::string_view name = colon == std::string_view::npos ? std::string_view() : line.substr(0, colon);
    if (!isVciToken(name)) {
        if (colon == std::string_view::npos && parseVciStartLine(line).ok) {
            // A new message begins here: the one before lost its empty line (or was garbage).
            m_pos = start;
            setError(VciErrorCode::MissingEmptyLine, "headers not ended by an empty line before the next message");
            return produce();
        }
        setError(VciErrorCode::BadHeader, "header line " + shown(line) + " is not \"Name: value\"");
        return Step::Continue;
    }
    const std::string_view value = trim(line.substr(colon + 1));
    for (char c : value) {
        const auto u = static_cast<unsigned char>(c);
        if ((u < 0x20 && c != '\t') || u == 0x7f) {
            setError(VciErrorCode::BadHeader, "header " + shown(name) + " holds a control character");
            return Step::Continue;
        }
    }
    if (++m_headerLines > m_limits.maxHeaders) {
        setError(VciErrorCode::TooManyHeaders, "more than " + std::to_string(m_limits.maxHeaders) + " header lines");
        return Step::Continue;
    }
    if (VciHeaders::namesEqual(name, "Content-Length")) {
        const auto length = parseLength(value);
        if (!length || (m_contentLength && *m_contentLength != *length)) {
            m_lengthBad = true;
            setError(VciErrorCode::BadContentLength,
                     length ? "two Content-Length headers disagree" : "Content-Length " + shown(value) + " is not a number");
        }
        m_contentLength = length;
    } else if (VciHeaders::namesEqual(name, "Content-Type")) {
        m_json = isJsonMediaType(value);
    }
    m_msg.headers.add(std::string(name), std::string(value));
    return Step::Continue;
}

VciParser::Step VciParser::endOfHeaders()
{
    if (m_lengthBad)
        return produceAndResync();
    if (m_contentLength) {
        if (*m_contentLength > m_limits.maxBodySize) {
            m_bad = false; // this one decides the framing, so it is the error to report
            setError(VciErrorCode::BodyTooLarge, "Content-Length " + std::to_string(*m_contentLength) + " is over the limit of "
                                                     + std::to_string(m_limits.maxBodySize) + " bytes");
            return produceAndResync();
        }
        if (*m_contentLength == 0)
            return produce();
        m_msg.hasBody = true;
        m_remaining = *m_contentLength;
        m_reader.reset();
        m_state = State::BodyLength;
        return Step::Continue;
    }
    if (m_json) {
        m_msg.hasBody = true;
        m_reader.reset();
        m_state = State::BodyJson;
        return Step::Continue;
    }
    return produce();
}

void VciParser::setReaderError()
{
    if (m_reader.decodedBytes() > m_limits.maxDecodedBytes)
        setError(VciErrorCode::BodyTooLarge, m_reader.error());
    else
        setError(VciErrorCode::BadJson, "body is not valid JSON: " + m_reader.error());
}

VciParser::Step VciParser::onBodyLength()
{
    const size_t take = size_t(std::min<uint64_t>(m_remaining, m_buf.size() - m_pos));
    if (take == 0)
        return Step::NeedMore;
    const char *p = m_buf.data() + m_pos;
    if (!m_bad && m_json) {
        size_t used = 0;
        if (m_reader.status() == VciJsonReader::Status::NeedMore)
            used = m_reader.feed(p, take);
        if (m_reader.status() == VciJsonReader::Status::Error) {
            setReaderError();
        } else if (m_reader.status() == VciJsonReader::Status::Done) {
            if (!std::all_of(p + used, p + take, isSpace))
                setError(VciErrorCode::BadJson, "body holds more than one JSON value");
        }
    } else if (!m_bad) {
        m_msg.rawBody.append(p, take);
    }
    m_pos += take;
    m_remaining -= take;
    if (m_remaining > 0)
        return Step::NeedMore;
    if (!m_bad && m_json) {
        if (m_reader.finish() == VciJsonReader::Status::Error) {
            setReaderError();
        } else {
            m_msg.body = m_reader.takeValue();
            m_msg.jsonBody = true;
        }
    }
    return produce();
}

VciParser::Step VciParser::onBodyJson()
{
    const size_t available = m_buf.size() - m_pos;
    if (available == 0)
        return Step::NeedMore;
    m_pos += m_reader.feed(m_buf.data() + m_pos, available);
    switch (m_reader.status()) {
    case VciJsonReader::Status::NeedMore:
        return Step::NeedMore;
    case VciJsonReader::Status::Done:
        m_msg.body = m_reader.takeValue();
        m_msg.jsonBody = true;
        return produce();
    case VciJsonReader::Status::Error:
        if (m_reader.consumed() >= m_limits.maxBodySize)
            setError(VciErrorCode::BodyTooLarge, "JSON body longer than the limit of " + std::to_string(m_limits.maxBodySize) + " bytes");
        else
            setReaderError();
        return produceAndResync();
    }
    return Step::NeedMore;
}

VciParser::Step VciParser::onResync()
{
    for (;;) {
        if (m_skipLine && !skipLongLineRest(true))
            return Step::NeedMore;
        const size_t before = m_pos;
        std::string_view line;
        size_t start = 0;
        const Line got = takeLine(&line, &start);
        if (got == Line::NeedMore)
            return Step::NeedMore;
        if (got == Line::TooLong) {
            m_discarded += m_pos - before;
            continue;
        }
        if (!line.empty() && parseVciStartLine(line).ok) {
            m_pos = start;
            m_state = State::StartLine;
            return Step::Continue;
        }
        m_discarded += m_pos - before;
    }
}

VciParseError VciParser::makeError() const
{
    VciParseError e;
    e.offset = m_msg.offset;
    e.code = m_errCode;
    e.message = m_errMessage;
    e.kindKnown = m_msgKindKnown;
    e.kind = m_msg.kind;
    e.verb = m_msg.kind == VciMessageKind::Request ? m_verbText : std::string();
    e.uri = m_msg.uri;
    return e;
}

VciParser::Step VciParser::produce()
{
    m_state = State::StartLine;
    m_msg.size = m_offset + m_pos - m_msg.offset;
    if (m_bad) {
        ++m_errors;
        m_result = makeError();
    } else {
        ++m_messages;
        m_result = std::move(m_msg);
    }
    return Step::Produced;
}

VciParser::Step VciParser::produceAndResync()
{
    produce();
    m_state = State::Resync;
    return Step::Produced;
}

} // namespace sortie::vci
