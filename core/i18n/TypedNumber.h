#pragma once

#include <QString>

#include <optional>

namespace sortie::i18n {

// Numbers the operator reads and types in a field, in the UI language's format: QLocale's default,
// which ui::Translations sets ("12,5" in German, "12.5" in English). Never a thousands separator:
// "1.500" must not be read as fifteen hundred in German nor as one and a half elsewhere by surprise.

// The language's format is tried first, then a dot decimal (a value pasted from a file or typed on
// habit); blanks around it are allowed. Empty, a group separator, or anything else: nullopt.
std::optional<double> parseTypedNumber(const QString &text);

// `decimals` places, or the shortest text that reads back as the same double when negative.
QString formatTypedNumber(double value, int decimals = -1);

} // namespace sortie::i18n
