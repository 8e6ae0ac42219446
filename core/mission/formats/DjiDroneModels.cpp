#include "DjiDroneModels.h"

#include <QStringList>

namespace sortie::mission::formats {

const std::vector<DjiDroneModel> &djiDroneModels()
{
    // Enumeration values (droneEnumValue/droneSubEnumValue, payloadEnumValue) from DJI's Cloud API
    // "Enumeration Values of Aircraft" and "of Camera" and the WPML common elements. Speeds and
    // limits from the aircraft's published specifications (waypoint flight: 15 m/s; M300/M350
    // altitude limit up to 1500 m, Mavic 3 Enterprise series up to 500 m above take-off). Where
    // Sortie has no published figure (the Matrice 30, 3D and 4 series, the Mavic 3M), the
    // limits checked are the Mavic 3 Enterprise's, the lower ones: a route they pass flies on those
    // aircraft. realTimeFollowSurface: the M3E/M3T/M3M only; startActionGroup: the M30, M3E and M3D
    // series (WPML's "Product Support").
    static const std::vector<DjiDroneModel> models = [] {
        const std::vector<DjiPayload> zenmuse = {
            {QStringLiteral("h20"), QStringLiteral("Zenmuse H20"), 42, 0, -120.0, 30.0},
            {QStringLiteral("h20t"), QStringLiteral("Zenmuse H20T"), 43, 0, -120.0, 30.0},
            {QStringLiteral("h20n"), QStringLiteral("Zenmuse H20N"), 61, 0, -120.0, 30.0},
            {QStringLiteral("p1"), QStringLiteral("Zenmuse P1"), 50, 0, -120.0, 30.0},
            {QStringLiteral("h30"), QStringLiteral("Zenmuse H30"), 82, 0, -120.0, 30.0},
            {QStringLiteral("h30t"), QStringLiteral("Zenmuse H30T"), 83, 0, -120.0, 30.0},
        };
        const auto camera = [](const char *key, const char *name, int enumValue) {
            return std::vector<DjiPayload>{{QString::fromLatin1(key), QString::fromLatin1(name), enumValue, 0, -90.0, 35.0}};
        };
        // The Mavic 3 Enterprise's limits, for the aircraft without published ones (see above).
        const auto mavicClass = [](const char *key, const char *name, int e, int sub, std::vector<DjiPayload> payloads, bool follows, bool start) {
            return DjiDroneModel{QString::fromLatin1(key), QString::fromLatin1(name), e, sub, std::move(payloads), 15.0, 21.0, 8.0, 6.0, 500.0, follows, start};
        };
        return std::vector<DjiDroneModel>{
            {QStringLiteral("m300"), QStringLiteral("DJI Matrice 300 RTK"), 60, 0, zenmuse, 15.0, 23.0, 6.0, 5.0, 1500.0, false, false},
            {QStringLiteral("m350"), QStringLiteral("DJI Matrice 350 RTK"), 89, 0, zenmuse, 15.0, 23.0, 6.0, 5.0, 1500.0, false, false},
            mavicClass("m30", "DJI Matrice 30", 67, 0, camera("m30-camera", "M30 camera", 52), false, true),
            mavicClass("m30t", "DJI Matrice 30T", 67, 1, camera("m30t-camera", "M30T camera", 53), false, true),
            mavicClass("m3e", "DJI Mavic 3 Enterprise", 77, 0, camera("m3e-camera", "Mavic 3E camera", 66), true, true),
            mavicClass("m3t", "DJI Mavic 3 Thermal", 77, 1, camera("m3t-camera", "Mavic 3T camera", 67), true, true),
            mavicClass("m3m", "DJI Mavic 3 Multispectral", 77, 2, camera("m3m-camera", "Mavic 3M camera", 68), true, true),
            mavicClass("m3d", "DJI Matrice 3D", 91, 0, camera("m3d-camera", "Matrice 3D camera", 80), false, true),
            mavicClass("m3td", "DJI Matrice 3TD", 91, 1, camera("m3td-camera", "Matrice 3TD camera", 81), false, true),
            // The Matrice 4 series: WPML's product-support lists do not name it for startActionGroup
            // or real-time terrain following, so neither is written for it.
            mavicClass("m4e", "DJI Matrice 4E", 99, 0, camera("m4e-camera", "Matrice 4E camera", 88), false, false),
            mavicClass("m4t", "DJI Matrice 4T", 99, 1, camera("m4t-camera", "Matrice 4T camera", 89), false, false),
            mavicClass("m4d", "DJI Matrice 4D", 100, 0, camera("m4d-camera", "Matrice 4D camera", 98), false, false),
            mavicClass("m4td", "DJI Matrice 4TD", 100, 1, camera("m4td-camera", "Matrice 4TD camera", 99), false, false),
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

const DjiDroneModel *findDjiDroneModel(int droneEnumValue, int droneSubEnumValue)
{
    for (const DjiDroneModel &m : djiDroneModels())
        if (m.droneEnumValue == droneEnumValue && m.droneSubEnumValue == droneSubEnumValue)
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
