#pragma once

// QNEAR: a number within a tolerance, naming both figures when it is not.
#include <QtTest>

#include <cmath>

#define QNEAR(actual, expected, tolerance)                                                                              \
    QVERIFY2(std::abs(double(actual) - double(expected)) <= (tolerance),                                               \
             qPrintable(QStringLiteral("%1 is %2, expected %3").arg(#actual).arg(double(actual), 0, 'g', 12).arg(double(expected))))
