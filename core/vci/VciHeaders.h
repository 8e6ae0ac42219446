#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sortie::vci {

// A message's header lines in wire order. Names compare case-insensitively (Content-Length,
// content-length and CONTENT-LENGTH are one header); values are kept as sent, trimmed of spaces.
class VciHeaders
{
public:
    using Entry = std::pair<std::string, std::string>;

    void add(std::string name, std::string value) { m_entries.emplace_back(std::move(name), std::move(value)); }
    // Replaces every header of that name by one (or adds it).
    void set(std::string_view name, std::string value);
    void remove(std::string_view name);

    // The first value of a header, or nullopt when it is absent.
    std::optional<std::string_view> value(std::string_view name) const;
    bool contains(std::string_view name) const { return value(name).has_value(); }

    const std::vector<Entry> &entries() const { return m_entries; }
    size_t size() const { return m_entries.size(); }
    bool empty() const { return m_entries.empty(); }
    void clear() { m_entries.clear(); }
    void reserve(size_t n) { m_entries.reserve(n); }

    static bool namesEqual(std::string_view a, std::string_view b);

private:
    std::vector<Entry> m_entries;
};

} // namespace sortie::vci
