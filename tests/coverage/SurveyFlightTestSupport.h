#pragma once
// The survey a vehicle flies in the coverage tests' heads (tst_coveragecli, tst_photosurvey), as
// its flight log and its camera's photos will hold it.
#include "GeotagTestSupport.h"
#include "LocalTangentPlane.h"

#include <QString>

#include <array>
#include <cmath>
#include <vector>

namespace sortie::test {

inline const QString kSurveyCamera = QStringLiteral("DJI Phantom 4 Pro / Phantom 4 RTK (FC6310)"); // 90 × 60 m from 60 m

// Five legs of 200 m, 27 m apart (70 % side overlap), flown at 6 m/s 60 m above a take-off at
// 40 m AMSL, a photo every 2 s (12 m: 80 % forward); 4.5 s to cross to the next leg.
struct SurveyFlight
{
    std::vector<std::array<double, 5>> samples; // ms, lat, lon, amsl, agl
    std::vector<std::pair<int64_t, int>> photos; // ms after the track's start, leg
};

inline SurveyFlight flySurvey()
{
    const mission::LocalTangentPlane plane({56.95, 24.10});
    SurveyFlight f;
    const double speed = 6, legLength = 200, spacing = 27, crossing = spacing / speed;
    const double legTime = legLength / speed;
    auto where = [&](double t, int *legOut) -> mission::PlanePoint {
        const double period = legTime + crossing;
        const int leg = std::min(4, int(t / period));
        const double in = t - leg * period;
        *legOut = leg;
        const bool north = leg % 2 == 0;
        if (in <= legTime || leg == 4) {
            const double along = std::min(in, legTime) * speed;
            return {leg * spacing, north ? along : legLength - along};
        }
        return {leg * spacing + (in - legTime) * speed, north ? legLength : 0}; // crossing east
    };
    const double end = 5 * legTime + 4 * crossing;
    for (double t = 0; t <= end + 1e-9; t += 0.5) {
        int leg = 0;
        const mission::GeoPoint p = plane.unproject(where(t, &leg));
        f.samples.push_back({t * 1000, p.latitude, p.longitude, 100, 60});
    }
    for (int leg = 0; leg < 5; ++leg)
        for (int j = 0; j <= 16; ++j)
            f.photos.push_back({int64_t(std::llround((leg * (legTime + crossing) + 2.0 * j) * 1000)), leg});
    return f;
}


// The survey's log (`folder`/survey.sortielog, vehicle EMU-101) and its photos on two cards:
// `folder`/card with every photo, `folder`/card-with-a-gap without the middle three legs' photos 6
// to 10 (72 to 120 m along). Empty, or what went wrong.
inline QString writeSurvey(const QString &folder, const SurveyFlight &flight)
{
    const QDir dir(folder);
    const QString error = writeFlightLog(dir.filePath(QStringLiteral("survey.sortielog")), {{QStringLiteral("VCI:emu"), QStringLiteral("EMU-101"), flight.samples}});
    if (!error.isEmpty())
        return error;
    const QDir card(dir.filePath(QStringLiteral("card"))), gappy(dir.filePath(QStringLiteral("card-with-a-gap")));
    if (!QDir().mkpath(card.path()) || !QDir().mkpath(gappy.path()))
        return QStringLiteral("cannot make the cards' folders in ") + folder;
    for (size_t i = 0; i < flight.photos.size(); ++i) {
        const QString name = QStringLiteral("DJI_%1.JPG").arg(i, 4, 10, QLatin1Char('0'));
        writeJpeg(card.filePath(name), int(i));
        setCameraTags(card.filePath(name), takenAt(flight.photos[i].first));
        const int along = int(i % 17), leg = flight.photos[i].second;
        if (!(leg >= 1 && leg <= 3 && along >= 6 && along <= 10) && !QFile::copy(card.filePath(name), gappy.filePath(name)))
            return QStringLiteral("cannot copy ") + name;
    }
    return {};
}

} // namespace sortie::test
