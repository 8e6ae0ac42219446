#include "DjiDroneModels.h"

#include <QStringList>

namespace sortie::mission::formats {

const std::vector<DjiDroneModel> &djiDroneModels()
{
    // Enumeration values from DJI's Cloud API "Product Support" page; speeds and limits from the
    // aircraft's published specifications (waypoint flight: 15 m/s; M300/M350 altitude limit up to
    // 1500 m, Mavic 3 Enterprise series up to 500 m above take-off).
    static const std::vector<DjiDroneModel> models = [] {
        const std::vector<DjiPayload> zenmuse = {
            {QStringLiteral("h20"), QStringLiteral("Zenmuse H20"), 42, 0, -120.0, 30.0},
            {QStringLiteral("h20t"), QStringLiteral("Zenmuse H20T"), 43, 0, -120.0, 30.0},
            {QStringLiteral("h20n"), QStringLiteral("Zenmuse H20N"), 61, 0, -120.0, 30.0},
            {QStringLiteral("p1"), QStringLiteral("Zenmuse P1"), 50, 0, -120.0, 30.0},
            {QStringLiteral("h30"), QStringLiteral("Zenmuse H30"), 82, 0, -120.0, 30.0},
            {QStringLiteral("h30t"), QStringLiteral("Zenmuse H30T"), 83, 0, -120.0, 30.0},
        };
        return std::vector<DjiDroneModel>{
            {QStringLiteral("m300"), QStringLiteral("DJI Matrice 300 RTK"), 60, 0, zenmuse, 15.0, 23.0, 6.0, 5.0, 1500.0, false},
            {QStringLiteral("m350"), QStringLiteral("DJI Matrice 350 RTK"), 89, 0, zenmuse, 15.0, 23.0, 6.0, 5.0, 1500.0, false},
            {QStringLiteral("m3e"), QStringLiteral("DJI Mavic 3 Enterprise"), 77, 0,
             {{QStringLiteral("m3e-camera"), QStringLiteral("Mavic 3E camera"), 66, 0, -90.0, 35.0}}, 15.0, 21.0, 8.0, 6.0, 500.0, true},
            {QStringLiteral("m3t"), QStringLiteral("DJI Mavic 3 Thermal"), 77, 1,
             {{QStringLiteral("m3t-camera"), QStringLiteral("Mavic 3T camera"), 67, 0, -90.0, 35.0}}, 15.0, 21.0, 8.0, 6.0, 500.0, true},
        };
    }();
    return models;
}

const DjiDroneModel *findDjiDroneModel(const QString &keyOrName)
{
    for (const DjiDroneModel &m : djiDroneModels())
        if (m.key.compare(keyOrName, Qt::CaseInsensitive) == 0 || m.name.compare(keyOrName, Qt::CaseInsensitive) == 0)
            return &m;
    return nullptr;
}

const DjiPayload *findDjiPayload(const DjiDroneModel &model, const QString &key)
{
    if (key.isEmpty())
        return model.payloads.empty() ? nullptr : &model.payloads.front();
    for (const DjiPayload &p : model.payloads)
        if (p.key.compare(key, Qt::CaseInsensitive) == 0 || p.name.compare(key, Qt::CaseInsensitive) == 0)
            return &p;
    return nullptr;
}

QString djiDroneKeys()
{
    QStringList keys;
    for (const DjiDroneModel &m : djiDroneModels())
        keys << m.key;
    return keys.join(QStringLiteral(", "));
}

} // namespace sortie::mission::formats
