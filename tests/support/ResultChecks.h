#pragma once
#include "core/support/Result.h"

#include <QTest>

// QVERIFY for a Result (core/support/Result.h): passes when it holds a value, else
// fails the test with the result's own error message.
#define QVERIFY_OK(expression)                                                                     \
    do {                                                                                           \
        const auto &result_ = (expression);                                                        \
        QVERIFY2(result_.ok(), qPrintable(result_.error()));                                       \
    } while (false)
