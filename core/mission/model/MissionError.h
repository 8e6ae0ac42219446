#pragma once

#include <QString>

#include <optional>
#include <utility>
#include <variant>

namespace sortie::mission {

// An error an operator can act on: what went wrong and where (file, line/column or JSON path).
struct MissionError
{
    QString message;
    QString file;      // empty when the input did not come from a file
    int line = 0;      // 1-based; 0 when unknown
    int column = 0;    // 1-based; 0 when unknown
    QString jsonPath;  // JSON pointer such as /mission/items/3/params/0; empty when not JSON

    // "plan.sortie:12:5: message", "plan.plan (at /mission/items/3): message" or just the message.
    QString toString() const;
    MissionError withFile(const QString &name) const;
};

// A value or the error that prevented it. No exceptions cross the public API.
template<typename T>
class Result
{
public:
    Result(T value) : m_data(std::move(value)) {}
    Result(MissionError error) : m_data(std::move(error)) {}

    bool ok() const { return m_data.index() == 0; }
    explicit operator bool() const { return ok(); }
    const T &value() const & { return std::get<0>(m_data); }
    T &value() & { return std::get<0>(m_data); }
    T &&value() && { return std::get<0>(std::move(m_data)); }
    const T &operator*() const { return value(); }
    const T *operator->() const { return &value(); }
    const MissionError &error() const { return std::get<1>(m_data); }

private:
    std::variant<T, MissionError> m_data;
};

template<>
class Result<void>
{
public:
    Result() = default;
    Result(MissionError error) : m_error(std::move(error)) {}
    bool ok() const { return !m_error; }
    explicit operator bool() const { return ok(); }
    const MissionError &error() const { return *m_error; }

private:
    std::optional<MissionError> m_error;
};

} // namespace sortie::mission
