// The closest point of approach of two constant-velocity states, against hand-worked figures.
#include "ClosestApproach.h"
#include "Near.h"

#include <QtTest>

using namespace sortie::deconfliction;

class TstClosestApproach : public QObject
{
    Q_OBJECT
private slots:
    // Head-on at 10 m/s each, 1000 m apart, the same height: the gap closes at 20 m/s, so it is
    // under 20 m while |1000 − 20t| < 20, t in (49, 51); they meet at t = 50.
    void headOn()
    {
        const Approach a = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 0, 100, -10, 0, 0}, 120);
        QVERIFY(a.conflict);
        QNEAR(a.conflict->begin, 49.0, 1e-9);
        QNEAR(a.conflict->end, 51.0, 1e-9);
        QNEAR(a.time, 50.0, 1e-9);
        QNEAR(a.horizontal, 0.0, 1e-9);
        QNEAR(a.vertical, 0.0, 1e-9);
    }

    // The same with b 30 m to the north: never closer than 30 m, at t = 50; no conflict.
    void passingWide()
    {
        const Approach a = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 30, 100, -10, 0, 0}, 120);
        QVERIFY(!a.conflict);
        QNEAR(a.time, 50.0, 1e-9);
        QNEAR(a.horizontal, 30.0, 1e-9);
    }

    // A horizon of 40 s ends before they meet: the closest is at its end, 1000 − 800 = 200 m.
    void theHorizonEndsFirst()
    {
        const Approach a = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 0, 100, -10, 0, 0}, 40);
        QVERIFY(!a.conflict);
        QNEAR(a.time, 40.0, 1e-9);
        QNEAR(a.horizontal, 200.0, 1e-9);
    }

    // b hovers 5 m away, 30 m lower, climbing at 2 m/s: the height difference |−30 + 2t| is under
    // 15 m for t in (7.5, 22.5). The horizontal distance holds, so the closest approach is the
    // smallest height difference: 0 at t = 15.
    void climbingUnderneath()
    {
        const Approach a = closestApproach({0, 0, 100, 0, 0, 0}, {5, 0, 70, 0, 0, 2}, 60);
        QVERIFY(a.conflict);
        QNEAR(a.conflict->begin, 7.5, 1e-9);
        QNEAR(a.conflict->end, 22.5, 1e-9);
        QNEAR(a.time, 15.0, 1e-9);
        QNEAR(a.horizontal, 5.0, 1e-9);
        QNEAR(a.vertical, 0.0, 1e-9);
    }

    // Head-on with b 14.9 m higher: a conflict, 14.9 m apart in height at t = 50; 15.1 m: none.
    void verticalSeparationAroundV()
    {
        const Approach below = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 0, 114.9, -10, 0, 0}, 120);
        QVERIFY(below.conflict);
        QNEAR(below.time, 50.0, 1e-9);
        QNEAR(below.vertical, 14.9, 1e-9);
        const Approach above = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 0, 115.1, -10, 0, 0}, 120);
        QVERIFY(!above.conflict);
        QNEAR(above.horizontal, 0.0, 1e-9);
    }

    // Side by side at the same velocity, 25 m apart: nothing changes, no conflict; 10 m apart with a
    // horizon of 0 (now only): a conflict at this moment.
    void constantGap()
    {
        const Approach wide = closestApproach({0, 0, 50, 5, 5, 0}, {25, 0, 50, 5, 5, 0}, 100);
        QVERIFY(!wide.conflict);
        QNEAR(wide.time, 0.0, 1e-9);
        QNEAR(wide.horizontal, 25.0, 1e-9);
        const Approach now = closestApproach({0, 0, 50, 0, 0, 0}, {10, 0, 50, 0, 0, 0}, 0);
        QVERIFY(now.conflict);
        QNEAR(now.conflict->begin, 0.0, 1e-9);
        QNEAR(now.conflict->end, 0.0, 1e-9);
        QNEAR(now.horizontal, 10.0, 1e-9);
    }

    // Separations of the caller's: at 500 m across, the head-on pair is in conflict while
    // |1000 − 20t| < 500, t in (25, 75).
    void ownSeparation()
    {
        const Approach a = closestApproach({0, 0, 100, 10, 0, 0}, {1000, 0, 100, -10, 0, 0}, 120, {500, 15});
        QVERIFY(a.conflict);
        QNEAR(a.conflict->begin, 25.0, 1e-9);
        QNEAR(a.conflict->end, 75.0, 1e-9);
    }
};

QTEST_APPLESS_MAIN(TstClosestApproach)
#include "tst_closestapproach.moc"
