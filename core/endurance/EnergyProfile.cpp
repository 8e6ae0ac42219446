#include "EnergyProfile.h"

#include "JsonCursor.h"
#include "MissionFiles.h"

#include <cmath>
#include <QCoreApplication>

namespace sortie::endurance {

using mission::MissionError;
using mission::formats::Json;
using mission::formats::JsonCursor;

double EnergyProfile::levelPowerW(double airSpeed) const
{
    const double v = std::max(0.0, airSpeed);
    if (cruiseSpeed <= 0)
        return hoverPowerW;
    const double r = v / cruiseSpeed;
    if (r <= 1.0)
        return hoverPowerW + (cruisePowerW - hoverPowerW) * r * r;
    return cruisePowerW * r * r * r;
}

QString EnergyProfile::problem() const
{
    struct Figure { const char *name; double value; };
    const Figure needed[] = {{"batteryWh", batteryWh}, {"cruiseSpeed", cruiseSpeed}, {"climbRate", climbRate},
                             {"descentRate", descentRate}, {"hoverPowerW", hoverPowerW}, {"cruisePowerW", cruisePowerW},
                             {"climbPowerW", climbPowerW}, {"descentPowerW", descentPowerW}};
    for (const Figure &f : needed)
        if (!(f.value > 0) || !std::isfinite(f.value))
            return QCoreApplication::translate("EnergyProfile", "%1 must be a positive number").arg(QLatin1String(f.name));
    if (!(reserve >= 0 && reserve < 1))
        return QCoreApplication::translate("EnergyProfile", "reserve must be a fraction from 0 up to (not including) 1");
    if (acceleration && !(*acceleration > 0))
        return QCoreApplication::translate("EnergyProfile", "acceleration must be a positive number");
    return {};
}

QString sourceName(ProfileSource source)
{
    switch (source) {
    case ProfileSource::File: return QStringLiteral("file");
    case ProfileSource::Server: return QStringLiteral("server");
    case ProfileSource::Fit: return QStringLiteral("fit");
    }
    return {};
}

mission::Result<EnergyProfile> readEnergyProfile(const QByteArray &json)
{
    mission::Result<Json> parsed = mission::formats::parseJson(json);
    if (!parsed)
        return parsed.error();
    try {
        const JsonCursor root(parsed.value());
        root.requireObject();
        EnergyProfile p;
        p.name = root.stringOr("name", {});
        const std::string source = root.text("source", "file"); // a copy: the fallback is a temporary
        if (source == "file")
            p.source = ProfileSource::File;
        else if (source == "server")
            p.source = ProfileSource::Server;
        else if (source == "fit")
            p.source = ProfileSource::Fit;
        else
            root.failAt("source", QCoreApplication::translate("EnergyProfile", "expected \"file\", \"server\" or \"fit\""));
        p.batteryWh = root.number("batteryWh");
        p.reserve = root.numberOr("reserve", 0.2);
        p.cruiseSpeed = root.number("cruiseSpeed");
        p.climbRate = root.number("climbRate");
        p.descentRate = root.number("descentRate");
        p.hoverPowerW = root.number("hoverPowerW");
        p.cruisePowerW = root.number("cruisePowerW");
        p.climbPowerW = root.number("climbPowerW");
        p.descentPowerW = root.number("descentPowerW");
        if (root.find("acceleration"))
            p.acceleration = root.number("acceleration");
        if (const QString problem = p.problem(); !problem.isEmpty())
            root.fail(problem);
        return p;
    } catch (const mission::formats::JsonPathError &e) {
        return mission::formats::errorAt(e);
    }
}

mission::Result<EnergyProfile> loadEnergyProfile(const QString &path)
{
    const mission::Result<QByteArray> data = mission::formats::readFileAtMost(path, 1024 * 1024);
    if (!data)
        return data.error();
    mission::Result<EnergyProfile> read = readEnergyProfile(data.value());
    if (!read)
        return read.error().withFile(path);
    return read;
}

QByteArray writeEnergyProfile(const EnergyProfile &p)
{
    Json j;
    if (!p.name.isEmpty())
        j["name"] = p.name.toStdString();
    j["source"] = sourceName(p.source).toStdString();
    j["batteryWh"] = p.batteryWh;
    j["reserve"] = p.reserve;
    j["cruiseSpeed"] = p.cruiseSpeed;
    j["climbRate"] = p.climbRate;
    j["descentRate"] = p.descentRate;
    j["hoverPowerW"] = p.hoverPowerW;
    j["cruisePowerW"] = p.cruisePowerW;
    j["climbPowerW"] = p.climbPowerW;
    j["descentPowerW"] = p.descentPowerW;
    if (p.acceleration)
        j["acceleration"] = *p.acceleration;
    return QByteArray::fromStdString(j.dump(2)) + '\n';
}

} // namespace sortie::endurance
