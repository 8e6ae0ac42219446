#include "AlgorithmProto.h"

#include "Domain.pb.h"

namespace sortie::mission {

namespace pb = com::ugcs::ucs::proto;

namespace {
QString text(const std::string &s) { return QString::fromStdString(s); }

Quantity quantityOf(pb::PhysicalSemantic s)
{
    switch (s) {
    case pb::PS_DISTANCE:
    case pb::PS_LENGTH: return Quantity::Distance;
    case pb::PS_ALTITUDE: return Quantity::Altitude;
    case pb::PS_SPEED: return Quantity::Speed;
    case pb::PS_VERTICAL_SPEED: return Quantity::VerticalSpeed;
    case pb::PS_AREA: return Quantity::Area;
    case pb::PS_GSD: return Quantity::Gsd;
    case pb::PS_ANGLE: return Quantity::Angle;
    case pb::PS_DURATION: return Quantity::Duration;
    default: return Quantity::None;
    }
}

pb::PhysicalSemantic semanticOf(Quantity q)
{
    switch (q) {
    case Quantity::Distance: return pb::PS_DISTANCE;
    case Quantity::Altitude: return pb::PS_ALTITUDE;
    case Quantity::Speed: return pb::PS_SPEED;
    case Quantity::VerticalSpeed: return pb::PS_VERTICAL_SPEED;
    case Quantity::Area: return pb::PS_AREA;
    case Quantity::Gsd: return pb::PS_GSD;
    case Quantity::Angle: return pb::PS_ANGLE;
    case Quantity::Duration: return pb::PS_DURATION;
    case Quantity::None:
    case Quantity::Percent:
    case Quantity::Count: break;
    }
    return pb::PS_NONE;
}

QString rangeText(const ParameterDefinition &p)
{
    if (!p.minimum && !p.maximum)
        return {};
    const QString unit = p.unit().isEmpty() ? QString() : QLatin1Char(' ') + p.unit();
    if (p.minimum && p.maximum)
        return QStringLiteral("%1–%2%3").arg(parameterNumberText(*p.minimum), parameterNumberText(*p.maximum), unit);
    if (p.minimum)
        return QStringLiteral("at least %1%2").arg(parameterNumberText(*p.minimum), unit);
    return QStringLiteral("at most %1%2").arg(parameterNumberText(*p.maximum), unit);
}
}

ParameterDefinition parameterFromProto(const pb::ParameterDefinition &in, const ParameterDefinition *known)
{
    ParameterDefinition p = known ? *known : ParameterDefinition{};
    p.name = text(in.name());
    if (p.displayName.isEmpty())
        p.displayName = p.name;
    if (in.has_description())
        p.description = text(in.description());
    if (in.has_type())
        p.type = ParameterType(int(in.type()));
    // Percent and Count have no wire semantic: keep what `known` says when the server sends none.
    if (in.has_physicalsemantic() && (in.physicalsemantic() != pb::PS_NONE || !known))
        p.quantity = quantityOf(in.physicalsemantic());
    if (in.has_defaultvalue())
        p.defaultValue = text(in.defaultvalue());
    if (in.has_mandatory())
        p.mandatory = in.mandatory();
    if (in.has_category())
        p.advanced = in.category() == pb::PG_ADVANCED;
    if (in.has_automatic())
        p.automatic = in.automatic();
    if (in.has_validationregex())
        p.validationRegex = text(in.validationregex());
    return p;
}

AlgorithmDefinition algorithmFromProto(const pb::TraverseAlgorithm &in, const AlgorithmCatalog *known)
{
    const QString className = text(in.implementationclass());
    const AlgorithmDefinition *base = known ? known->byClassName(className) : nullptr;
    AlgorithmDefinition a;
    a.className = className;
    a.kind = base ? base->kind : algorithmKindOf(className);
    a.displayName = in.has_name() ? text(in.name()) : base ? base->displayName : className.section(QLatin1Char('.'), -1);
    a.code = text(in.code());
    a.serverId = in.id();
    a.figure = in.has_figuretype() ? FigureType(int(in.figuretype())) : base ? base->figure : FigureType::Point;
    a.minimumPoints = base ? base->minimumPoints
                    : a.figure == FigureType::Polygon ? 3 : a.figure == FigureType::Polyline ? 2 : 1;
    for (const auto &d : in.parameterdefinitions())
        a.parameters.push_back(parameterFromProto(d, base ? base->parameter(text(d.name())) : nullptr));
    return a;
}

pb::TraverseAlgorithm algorithmToProto(const AlgorithmDefinition &a)
{
    pb::TraverseAlgorithm out;
    if (a.serverId)
        out.set_id(a.serverId);
    out.set_name(a.displayName.toStdString());
    out.set_implementationclass(a.className.toStdString());
    out.set_selectfigure(true);
    out.set_figuretype(pb::FigureType(int(a.figure)));
    if (!a.code.isEmpty())
        out.set_code(a.code.toStdString());
    for (const ParameterDefinition &p : a.parameters) {
        auto *d = out.add_parameterdefinitions();
        d->set_name(p.name.toStdString());
        QString description = p.description.isEmpty() ? p.displayName : p.description;
        if (const QString range = rangeText(p); !range.isEmpty())
            description += QStringLiteral(" (%1)").arg(range);
        d->set_description(description.toStdString());
        d->set_type(pb::ParameterType(int(p.type)));
        d->set_mandatory(p.mandatory);
        d->set_defaultvalue(p.defaultValue.toStdString());
        if (!p.validationRegex.isEmpty())
            d->set_validationregex(p.validationRegex.toStdString());
        d->set_physicalsemantic(semanticOf(p.quantity));
        d->set_category(p.advanced ? pb::PG_ADVANCED : pb::PG_BASIC);
        d->set_automatic(p.automatic);
    }
    return out;
}

AlgorithmCatalog catalogFromProto(const std::vector<pb::TraverseAlgorithm> &algorithms, const AlgorithmCatalog &known)
{
    AlgorithmCatalog catalog;
    for (const pb::TraverseAlgorithm &a : algorithms)
        catalog.insert(algorithmFromProto(a, &known));
    for (const AlgorithmDefinition &a : known.algorithms())
        if (!catalog.byClassName(a.className))
            catalog.insert(a);
    return catalog;
}

void applySelections(AlgorithmDefinition &algorithm, const std::vector<pb::Selection> &selections)
{
    for (const pb::Selection &selection : selections) {
        for (ParameterDefinition &p : algorithm.parameters) {
            if (p.name != text(selection.selectionid()))
                continue;
            p.choices.clear();
            for (const auto &item : selection.items()) {
                const QString value = text(item.value());
                p.choices.push_back({value, item.description().empty() ? value : text(item.description())});
                if (item.markdefault() && p.defaultValue.isEmpty())
                    p.defaultValue = value;
            }
        }
    }
}

} // namespace sortie::mission
