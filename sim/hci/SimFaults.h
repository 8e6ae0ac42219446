#pragma once

#include <QSet>

namespace sortie::sim {

// Test knobs of the simulated server, read live by every connection. All off by default.
struct SimFaults
{
    int reverseBatch = 0;          // hold answers until this many wait, then send them newest first
    int delayMs = 0;               // delay every answer by this much
    QSet<int> dropAnswersTo;       // request type numbers whose answers are never sent
    int dropNextAnswers = 0;       // the next N answers are never sent (counts down)
    int malformedBeforeAnswers = 0;// the next N answers each follow a malformed frame (counts down)
    QSet<int> disconnectOn;        // request type numbers on which the server drops the connection unanswered
};

} // namespace sortie::sim
