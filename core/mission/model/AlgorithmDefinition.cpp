#include "AlgorithmDefinition.h"

#include <QRegularExpression>

#include <cmath>
#include <QCoreApplication>

namespace sortie::mission {

QString unitSymbol(Quantity q)
{
    switch (q) {
    case Quantity::Distance:
    case Quantity::Altitude: return QStringLiteral("m");
    case Quantity::Speed:
    case Quantity::VerticalSpeed: return QStringLiteral("m/s");
    case Quantity::Area: return QStringLiteral("m²");
    case Quantity::Gsd: return QStringLiteral("cm/px");
    case Quantity::Angle: return QStringLiteral("°");
    case Quantity::Duration: return QStringLiteral("s");
    case Quantity::Percent: return QStringLiteral("%");
    case Quantity::None:
    case Quantity::Count: break;
    }
    return {};
}

std::optional<double> parseParameterNumber(const QString &text)
{
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<bool> parseParameterBoolean(const QString &text)
{
    const QString t = text.trimmed();
    if (t.compare(QLatin1String("true"), Qt::CaseInsensitive) == 0)
        return true;
    if (t.compare(QLatin1String("false"), Qt::CaseInsensitive) == 0)
        return false;
    return std::nullopt;
}

QString parameterNumberText(double v)
{
    const QString shortText = QString::number(v, 'g', 15);
    return shortText.toDouble() == v ? shortText : QString::number(v, 'g', 17);
}

namespace {
QString withUnit(double v, const ParameterDefinition &d)
{
    const QString u = d.unit();
    return u.isEmpty() ? parameterNumberText(v) : parameterNumberText(v) + QLatin1Char(' ') + u;
}
}

QString ParameterDefinition::check(const QString &value) const
{
    if (value.trimmed().isEmpty()) {
        if (mandatory && defaultValue.isEmpty())
            return QCoreApplication::translate("AlgorithmDefinition", "%1 must be set").arg(name);
        return {};
    }
    switch (type) {
    case ParameterType::Integer:
    case ParameterType::Double: {
        const auto v = parseParameterNumber(value);
        if (!v)
            return QCoreApplication::translate("AlgorithmDefinition", "%1: '%2' is not a number").arg(name, value);
        if (type == ParameterType::Integer && std::floor(*v) != *v)
            return QCoreApplication::translate("AlgorithmDefinition", "%1: '%2' is not a whole number").arg(name, value);
        if (minimum && *v < *minimum)
            return QCoreApplication::translate("AlgorithmDefinition", "%1: %2 is below the minimum of %3").arg(name, parameterNumberText(*v), withUnit(*minimum, *this));
        if (maximum && *v > *maximum)
            return QCoreApplication::translate("AlgorithmDefinition", "%1: %2 is above the maximum of %3").arg(name, parameterNumberText(*v), withUnit(*maximum, *this));
        break;
    }
    case ParameterType::Boolean:
        if (!parseParameterBoolean(value))
            return QCoreApplication::translate("AlgorithmDefinition", "%1: '%2' is neither true nor false").arg(name, value);
        break;
    case ParameterType::Selection:
        if (!choices.empty()) {
            bool known = false;
            for (const ParameterChoice &c : choices)
                known = known || c.value == value.trimmed();
            if (!known)
                return QCoreApplication::translate("AlgorithmDefinition", "%1: '%2' is not one of its choices").arg(name, value);
        }
        break;
    case ParameterType::String:
        break;
    }
    if (!validationRegex.isEmpty()) {
        const QRegularExpression re(QRegularExpression::anchoredPattern(validationRegex));
        if (re.isValid() && !re.match(value).hasMatch())
            return QCoreApplication::translate("AlgorithmDefinition", "%1: '%2' does not have the expected form").arg(name, value);
    }
    return {};
}

const ParameterDefinition *AlgorithmDefinition::parameter(QStringView name) const
{
    for (const ParameterDefinition &p : parameters)
        if (p.name == name)
            return &p;
    return nullptr;
}

std::optional<QString> ParameterReader::text(QStringView name) const
{
    for (const ParameterValue &v : m_values)
        if (v.name == name)
            return v.value;
    return std::nullopt;
}

std::optional<QString> ParameterReader::effective(QStringView name) const
{
    const auto given = text(name);
    if (given && !given->trimmed().isEmpty())
        return given;
    if (const ParameterDefinition *d = m_algorithm.parameter(name); d && !d->defaultValue.isEmpty())
        return d->defaultValue;
    return std::nullopt;
}

std::optional<double> ParameterReader::number(QStringView name) const
{
    const auto given = text(name);
    if (given)
        if (const auto v = parseParameterNumber(*given))
            return v;
    if (const ParameterDefinition *d = m_algorithm.parameter(name))
        return parseParameterNumber(d->defaultValue);
    return std::nullopt;
}

std::optional<bool> ParameterReader::boolean(QStringView name) const
{
    const auto given = text(name);
    if (given)
        if (const auto v = parseParameterBoolean(*given))
            return v;
    if (const ParameterDefinition *d = m_algorithm.parameter(name))
        return parseParameterBoolean(d->defaultValue);
    return std::nullopt;
}

QString ParameterReader::selection(QStringView name) const
{
    return effective(name).value_or(QString()).trimmed();
}

std::vector<QString> ParameterReader::problems() const
{
    std::vector<QString> out;
    for (const ParameterDefinition &d : m_algorithm.parameters) {
        const QString problem = d.check(text(d.name).value_or(QString()));
        if (!problem.isEmpty())
            out.push_back(problem);
    }
    return out;
}

} // namespace sortie::mission
