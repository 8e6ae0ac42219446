#include "VciHeaders.h"

#include <algorithm>

namespace sortie::vci {

bool VciHeaders::namesEqual(std::string_view a, std::string_view b)
{
    if (a.size() != b.size())
        return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c + 32) : c; };
        if (lower(a[i]) != lower(b[i]))
            return false;
    }
    return true;
}

void VciHeaders::set(std::string_view name, std::string value)
{
    remove(name);
    add(std::string(name), std::move(value));
}

void VciHeaders::remove(std::string_view name)
{
    std::erase_if(m_entries, [name](const Entry &e) { return namesEqual(e.first, name); });
}

std::optional<std::string_view> VciHeaders::value(std::string_view name) const
{
    for (const Entry &e : m_entries) {
        if (namesEqual(e.first, name))
            return std::string_view(e.second);
    }
    return std::nullopt;
}

} // namespace sortie::vci
