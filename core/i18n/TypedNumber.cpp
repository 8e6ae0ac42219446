#include "TypedNumber.h"

#include <QLocale>

namespace sortie::i18n {

std::optional<double> parseTypedNumber(const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return std::nullopt;
    for (QLocale locale : {QLocale(), QLocale::c()}) {
        locale.setNumberOptions(QLocale::RejectGroupSeparator);
        bool ok = false;
        const double value = locale.toDouble(trimmed, &ok);
        if (ok)
            return value;
    }
    return std::nullopt;
}

QString formatTypedNumber(double value, int decimals)
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return decimals < 0 ? locale.toString(value, 'g', QLocale::FloatingPointShortest) : locale.toString(value, 'f', decimals);
}

} // namespace sortie::i18n
