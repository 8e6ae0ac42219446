#pragma once

#include "MissionError.h"

#include <QByteArray>
#include <QString>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <QCoreApplication>

namespace sortie::mission::formats {

using Json = nlohmann::ordered_json;

// Thrown inside a reader only; readers catch it and return a MissionError with the JSON path.
struct JsonPathError
{
    std::string path;
    QString message;
};

// A position in a parsed JSON document that knows its JSON pointer, so that every complaint
// names where it is: "/mission/items/3/params/0: expected a number".
class JsonCursor
{
public:
    JsonCursor(const Json &value, std::string path = {}) : m_value(&value), m_path(std::move(path)) {}

    const Json &value() const { return *m_value; }
    const std::string &path() const { return m_path; }
    QString pathText() const { return m_path.empty() ? QStringLiteral("/") : QString::fromStdString(m_path); }

    JsonCursor at(const char *key) const;              // a required member
    std::optional<JsonCursor> find(const char *key) const;
    JsonCursor at(size_t index) const;                 // an array element
    size_t arraySize() const;                          // fails unless an array
    void requireObject() const;

    double number() const;                             // finite numbers only
    double number(const char *key) const;
    double numberOr(const char *key, double fallback) const;
    int integer() const;
    int integerOr(const char *key, int fallback) const;
    bool boolean() const;
    bool booleanOr(const char *key, bool fallback) const;
    QString string() const;
    QString stringOr(const char *key, const QString &fallback) const;
    // A member string without conversion (for enum names); fallback when absent.
    const std::string &text(const char *key, const std::string &fallback) const;
    bool isNull() const { return m_value->is_null(); }

    [[noreturn]] void fail(const QString &message) const;
    [[noreturn]] void failAt(const char *key, const QString &message) const;

private:
    // Scalar members are read without building a child path: it is only needed for an error.
    const Json *member(const char *key) const;
    static double toNumber(const Json &v, const JsonCursor &where, const char *key);

    const Json *m_value;
    std::string m_path;
};

// Parses text as JSON. A syntax error comes back with its 1-based line and column.
Result<Json> parseJson(const QByteArray &data);
MissionError errorAt(const JsonPathError &e);

// The index of the cursor's string in `names` (a file's spelling of an enum, in the enum's order);
// an unknown name fails at the cursor.
template<size_t N>
int indexOf(const char *const (&names)[N], const JsonCursor &c)
{
    const std::string s = c.string().toStdString();
    for (size_t i = 0; i < N; ++i)
        if (s == names[i])
            return int(i);
    c.fail(QCoreApplication::translate("JsonCursor", "unknown value \"%1\"").arg(QString::fromStdString(s)));
}

} // namespace sortie::mission::formats
