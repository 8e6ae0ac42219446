// Phase segmentation and the fit on synthetic traces: every sample's speeds and power written by
// the test, so what each phase should give is known exactly.
#include "EnergyFit.h"
#include "PhaseSegmenter.h"

#include <QtTest>

using namespace sortie::endurance;
using namespace sortie::endurance::fit;

namespace {

// A flight built leg by leg at 2 samples a second; power per leg, the remaining fraction following
// the energy drawn from a battery of `capacityWh`.
class SyntheticFlight
{
public:
    explicit SyntheticFlight(double capacityWh = 100) : m_capacityWh(capacityWh) {}
    SyntheticFlight &leg(double seconds, double gs, double vz, double powerW, double agl = 30, bool armed = true)
    {
        for (int i = 0; i < int(seconds * 2); ++i) {
            PowerSample s;
            s.time = m_time;
            s.groundSpeed = gs;
            s.verticalSpeed = vz;
            s.altitudeAgl = agl;
            s.armed = armed ? 1 : 0;
            s.remaining = m_remaining;
            s.powerW = powerW;
            m_trace.samples.push_back(s);
            m_time += 500;
            m_remaining -= powerW * 0.5 / 3600.0 / m_capacityWh;
        }
        return *this;
    }
    FlightTrace trace(bool withCurrent = true) const
    {
        FlightTrace t = m_trace;
        t.name = QStringLiteral("synthetic");
        t.currentReported = withCurrent;
        if (!withCurrent)
            for (PowerSample &s : t.samples)
                s.powerW = kMissing;
        return t;
    }

private:
    double m_capacityWh;
    FlightTrace m_trace;
    int64_t m_time = 1'780'000'000'000;
    double m_remaining = 1.0;
};

// Ground, take-off climb, hover, cruise at 10 m/s, a climb, a descent, landing.
SyntheticFlight typicalFlight()
{
    SyntheticFlight f;
    f.leg(5, 0, 0, 20, 0).leg(10, 0, 3, 400).leg(30, 0, 0, 300).leg(60, 10, 0, 260).leg(10, 0, 3, 400)
        .leg(20, 0, -2, 210).leg(5, 0, 0, 0, 0, false);
    return f;
}

} // namespace

class TstEnergyFit : public QObject
{
    Q_OBJECT
private slots:
    void classifiesBySpeeds()
    {
        PowerSample s;
        s.altitudeAgl = 30;
        s.armed = 1;
        const auto at = [&](double gs, double vz) { s.groundSpeed = gs; s.verticalSpeed = vz; return classify(s); };
        QCOMPARE(at(0.1, 0.05), Phase::Hover);
        QCOMPARE(at(8, 0.1), Phase::Level);
        QCOMPARE(at(0.6, 0.0), Phase::Transition); // creeping: neither hover nor cruise
        QCOMPARE(at(0.2, 3), Phase::Climb);
        QCOMPARE(at(0.2, -2), Phase::Descent);
        QCOMPARE(at(8, 2), Phase::Transition);     // climbing along a leg: not a straight climb
        s.altitudeAgl = 0.5;
        QCOMPARE(at(0, 0), Phase::Ground);
        s.altitudeAgl = kMissing;
        s.armed = 0;  // without a height, disarmed is on the ground
        QCOMPARE(at(0, 0), Phase::Ground);
        s.armed = kMissing;  // and unknown arming does not make it grounded
        s.groundSpeed = kMissing;
        QCOMPARE(classify(s), Phase::Transition);
    }

    void segmentsAndTrimsTransitions()
    {
        const FlightTrace t = typicalFlight().trace();
        const std::vector<PhaseRun> runs = segmentPhases(t.samples);
        const std::vector<Phase> expected{Phase::Climb, Phase::Hover, Phase::Level, Phase::Climb, Phase::Descent};
        QCOMPARE(runs.size(), expected.size());
        for (size_t i = 0; i < runs.size(); ++i) {
            QCOMPARE(runs[i].phase, expected[i]);
            // 2 s trimmed at each end: the first kept sample is 2 s into its phase.
            const PowerSample &first = t.samples[runs[i].first];
            QCOMPARE(classify(t.samples[runs[i].first - 4]), runs[i].phase);
            QVERIFY(classify(t.samples[runs[i].first - 5]) != runs[i].phase);
            QCOMPARE(classify(t.samples[runs[i].last + 4]), runs[i].phase);
            QVERIFY(classify(t.samples[runs[i].last + 5]) != runs[i].phase);
            QVERIFY(first.time <= t.samples[runs[i].last].time);
        }
        // The hover's 30 s keep 2 s to 27.5 s: 52 samples at 2 a second.
        QCOMPARE(runs[1].last - runs[1].first + 1, size_t(52));
    }

    void shortRunsAndGapsAreLeftOut()
    {
        SyntheticFlight f;
        f.leg(20, 0, 0, 300).leg(3, 8, 0, 250).leg(20, 0, 0, 300);  // 3 s of level: nothing left after trimming
        FlightTrace t = f.trace();
        std::vector<PhaseRun> runs = segmentPhases(t.samples);
        QCOMPARE(runs.size(), size_t(2));
        QCOMPARE(runs[0].phase, Phase::Hover);
        QCOMPARE(runs[1].phase, Phase::Hover);
        // A 10 s hole in the telemetry splits a hover in two.
        SyntheticFlight g;
        g.leg(20, 0, 0, 300);
        t = g.trace();
        for (size_t i = 20; i < t.samples.size(); ++i)
            t.samples[i].time += 10000;
        runs = segmentPhases(t.samples);
        QCOMPARE(runs.size(), size_t(2));
    }

    void fitsEachPhaseAndTheCapacity()
    {
        const EnergyFit fit = fitEnergy({typicalFlight().trace(), typicalFlight().trace()});
        QCOMPARE(fit.flights, 2);
        QVERIFY(fit.hoverPowerW.ok());
        QCOMPARE(*fit.hoverPowerW.value, 300.0);
        QCOMPARE(fit.hoverPowerW.spread, 0.0);
        QCOMPARE(fit.hoverPowerW.count, 2 * 52);
        QCOMPARE(*fit.cruisePowerW.value, 260.0);
        QCOMPARE(*fit.cruiseSpeed.value, 10.0);
        QCOMPARE(*fit.climbPowerW.value, 400.0);
        QCOMPARE(*fit.climbRate.value, 3.0);
        QCOMPARE(*fit.descentPowerW.value, 210.0);
        QCOMPARE(*fit.descentRate.value, 2.0);
        QVERIFY2(std::abs(*fit.batteryWh.value - 100.0) < 0.5, qPrintable(QString::number(*fit.batteryWh.value)));
        QCOMPARE(fit.batteryWh.count, 2);
        const auto profile = fit.profile(QStringLiteral("quad"));
        QVERIFY(profile);
        QCOMPARE(profile->source, ProfileSource::Fit);
        QCOMPARE(profile->hoverPowerW, 300.0);
        QVERIFY(profile->problem().isEmpty());
    }

    void theMostFlownSpeedIsTheCruise()
    {
        SyntheticFlight f;
        f.leg(30, 6, 0, 240).leg(80, 12, 0, 330).leg(30, 6, 0, 240);
        const EnergyFit fit = fitEnergy({f.trace()});
        QCOMPARE(*fit.cruiseSpeed.value, 12.0);
        QCOMPARE(*fit.cruisePowerW.value, 330.0);
    }

    void aPhaseWithTooLittleDataIsMissingNotZero()
    {
        SyntheticFlight f;
        f.leg(40, 0, 0, 300).leg(8, 0, 3, 400).leg(40, 9, 0, 250);  // 4 s of climb left after trimming: 8 samples
        const EnergyFit fit = fitEnergy({f.trace()});
        QVERIFY(fit.hoverPowerW.ok());
        QVERIFY(!fit.climbPowerW.ok());
        QVERIFY2(fit.climbPowerW.missing.startsWith(QLatin1String("too little straight climb")), qPrintable(fit.climbPowerW.missing));
        QVERIFY(!fit.descentPowerW.ok());
        QCOMPARE(fit.descentPowerW.missing, QStringLiteral("no straight descent in the logs"));
        QString why;
        QVERIFY(!fit.profile(QStringLiteral("x"), &why));
        QVERIFY2(why.contains(QLatin1String("climb power")), qPrintable(why));
    }

    // Without current, powers come from the remaining fraction's drop times a capacity: fitted
    // from another log that has current, else the one given, else none at all.
    void remainingFractionWithAKnownCapacity()
    {
        const FlightTrace withoutCurrent = typicalFlight().trace(false);
        EnergyFit fit = fitEnergy({withoutCurrent});
        QVERIFY(!fit.batteryWh.ok());
        QVERIFY(!fit.hoverPowerW.ok());
        QCOMPARE(fit.flights, 0);
        QCOMPARE(fit.notes.size(), 1);

        FitOptions given;
        given.capacityWh = 100;
        fit = fitEnergy({withoutCurrent}, given);
        QCOMPARE(fit.capacitySource, QStringLiteral("given (--capacity)"));
        QVERIFY(std::abs(*fit.hoverPowerW.value - 300) < 3);
        QVERIFY(std::abs(*fit.cruisePowerW.value - 260) < 3);
        QVERIFY(std::abs(*fit.climbPowerW.value - 400) < 4);

        fit = fitEnergy({withoutCurrent, typicalFlight().trace()});
        QVERIFY(fit.capacitySource.startsWith(QLatin1String("fitted")));
        QCOMPARE(fit.flights, 2);
        QVERIFY(std::abs(*fit.hoverPowerW.value - 300) < 3);
    }
};

QTEST_GUILESS_MAIN(TstEnergyFit)
#include "tst_energyfit.moc"
