#include "JsonCursor.h"

#include <QRegularExpression>

#include <cmath>
#include <QCoreApplication>

namespace sortie::mission::formats {

namespace {
std::string escapeToken(const char *key)
{
    std::string out;
    for (const char *c = key; *c; ++c) {
        if (*c == '~') out += "~0";
        else if (*c == '/') out += "~1";
        else out += *c;
    }
    return out;
}

const char *typeName(const Json &j)
{
    return j.type_name();
}
}

void JsonCursor::fail(const QString &message) const
{
    throw JsonPathError{m_path.empty() ? std::string("/") : m_path, message};
}

void JsonCursor::requireObject() const
{
    if (!m_value->is_object())
        fail(QCoreApplication::translate("JsonCursor", "expected an object, found %1").arg(QLatin1String(typeName(*m_value))));
}

std::optional<JsonCursor> JsonCursor::find(const char *key) const
{
    requireObject();
    const auto it = m_value->find(key);
    if (it == m_value->end())
        return std::nullopt;
    return JsonCursor(*it, m_path + "/" + escapeToken(key));
}

JsonCursor JsonCursor::at(const char *key) const
{
    if (auto c = find(key))
        return *c;
    fail(QCoreApplication::translate("JsonCursor", "missing required key \"%1\"").arg(QLatin1String(key)));
}

size_t JsonCursor::arraySize() const
{
    if (!m_value->is_array())
        fail(QCoreApplication::translate("JsonCursor", "expected an array, found %1").arg(QLatin1String(typeName(*m_value))));
    return m_value->size();
}

JsonCursor JsonCursor::at(size_t index) const
{
    if (index >= arraySize())
        fail(QCoreApplication::translate("JsonCursor", "expected at least %1 elements, found %2").arg(index + 1).arg(m_value->size()));
    return JsonCursor((*m_value)[index], m_path + "/" + std::to_string(index));
}

const Json *JsonCursor::member(const char *key) const
{
    requireObject();
    const auto it = m_value->find(key);
    return it == m_value->end() ? nullptr : &*it;
}

void JsonCursor::failAt(const char *key, const QString &message) const
{
    throw JsonPathError{m_path + "/" + escapeToken(key), message};
}

double JsonCursor::toNumber(const Json &v, const JsonCursor &where, const char *key)
{
    auto fail = [&](const QString &m) { key ? where.failAt(key, m) : where.fail(m); };
    if (!v.is_number())
        fail(QCoreApplication::translate("JsonCursor", "expected a number, found %1").arg(QLatin1String(typeName(v))));
    const double d = v.get<double>();
    if (!std::isfinite(d))
        fail(QCoreApplication::translate("JsonCursor", "the number is not finite"));
    return d;
}

double JsonCursor::number() const
{
    return toNumber(*m_value, *this, nullptr);
}

double JsonCursor::number(const char *key) const
{
    const Json *v = member(key);
    if (!v)
        failAt(key, QCoreApplication::translate("JsonCursor", "missing required key \"%1\"").arg(QLatin1String(key)));
    return toNumber(*v, *this, key);
}

double JsonCursor::numberOr(const char *key, double fallback) const
{
    const Json *v = member(key);
    return v && !v->is_null() ? toNumber(*v, *this, key) : fallback;
}

int JsonCursor::integer() const
{
    const double v = number();
    if (v != std::floor(v) || std::abs(v) > 2147483647.0)
        fail(QCoreApplication::translate("JsonCursor", "expected an integer, found %1").arg(v));
    return int(v);
}

int JsonCursor::integerOr(const char *key, int fallback) const
{
    const auto c = find(key);
    return c && !c->isNull() ? c->integer() : fallback;
}

bool JsonCursor::boolean() const
{
    if (!m_value->is_boolean())
        fail(QCoreApplication::translate("JsonCursor", "expected true or false, found %1").arg(QLatin1String(typeName(*m_value))));
    return m_value->get<bool>();
}

bool JsonCursor::booleanOr(const char *key, bool fallback) const
{
    const Json *v = member(key);
    if (!v || v->is_null())
        return fallback;
    if (!v->is_boolean())
        failAt(key, QCoreApplication::translate("JsonCursor", "expected true or false, found %1").arg(QLatin1String(typeName(*v))));
    return v->get<bool>();
}

const std::string &JsonCursor::text(const char *key, const std::string &fallback) const
{
    const Json *v = member(key);
    if (!v || v->is_null())
        return fallback;
    if (!v->is_string())
        failAt(key, QCoreApplication::translate("JsonCursor", "expected a string, found %1").arg(QLatin1String(typeName(*v))));
    return v->get_ref<const std::string &>();
}

QString JsonCursor::string() const
{
    if (!m_value->is_string())
        fail(QCoreApplication::translate("JsonCursor", "expected a string, found %1").arg(QLatin1String(typeName(*m_value))));
    return QString::fromStdString(m_value->get_ref<const std::string &>());
}

QString JsonCursor::stringOr(const char *key, const QString &fallback) const
{
    const Json *v = member(key);
    if (!v || v->is_null())
        return fallback;
    if (!v->is_string())
        failAt(key, QCoreApplication::translate("JsonCursor", "expected a string, found %1").arg(QLatin1String(typeName(*v))));
    return QString::fromStdString(v->get_ref<const std::string &>());
}

namespace {
MissionError syntaxError(const QByteArray &data, qsizetype byte, QString what)
{
    int line = 1, column = 1;
    for (qsizetype i = 0; i < qBound<qsizetype>(0, byte, data.size()); ++i) {
        if (data[i] == '\n') { ++line; column = 1; }
        else ++column;
    }
    return MissionError{QCoreApplication::translate("JsonCursor", "not valid JSON: %1").arg(what), {}, line, column, {}};
}
}

Result<Json> parseJson(const QByteArray &data)
{
    try {
        return Json::parse(data.constBegin(), data.constEnd());
    } catch (const Json::parse_error &e) {
        // "[json.exception...] parse error at line L, column C: <what>; last read: '<text>'; <expected>"
        QString what = QString::fromUtf8(e.what());
        const qsizetype colon = what.indexOf(QStringLiteral(": "));
        if (colon >= 0)
            what = what.mid(colon + 2);
        static const QRegularExpression lastRead(QStringLiteral("; last read: '.*'"), QRegularExpression::DotMatchesEverythingOption);  // i18n: not text (matches the JSON library's own English message)
        what.remove(lastRead);
        return syntaxError(data, qsizetype(e.byte) - 1, what);  // e.byte is 1-based, just past the error
    } catch (const Json::exception &e) {
        // A number too large for a double: "number overflow parsing '<token>'". Locate the token.
        QString what = QString::fromUtf8(e.what());
        what.remove(QRegularExpression(QStringLiteral("^\\[[^]]*\\] ")));
        const qsizetype open = what.indexOf(QLatin1Char('\'')), close = what.lastIndexOf(QLatin1Char('\''));
        qsizetype at = -1;
        if (open >= 0 && close > open)
            at = data.indexOf(what.mid(open + 1, close - open - 1).toUtf8());
        return syntaxError(data, at < 0 ? 0 : at, what);
    }
}

MissionError errorAt(const JsonPathError &e)
{
    return MissionError{e.message, {}, 0, 0, QString::fromStdString(e.path)};
}

} // namespace sortie::mission::formats
