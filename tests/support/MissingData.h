#pragma once
// Skipping a case whose data is missing: the default head (fetched from the npm registry at
// set-up) or the reference material in ../shared. Under CI=true, which CI sets, a missing file
// fails the case instead, naming it: a failed fetch or an unmounted ../shared cannot pass CI as a
// run of skips. Locally a skip stays a skip. QSKIP and QFAIL end only the function they are
// written in, so these are macros that expand inside each case.
#include <QFileInfo>
#include <QString>
#include <QtGlobal>
#include <QtTest>

namespace lacrima::testsupport {

inline bool missingDataFails() { return qEnvironmentVariable("CI") == QLatin1String("true"); }

// What a case says when `what` is missing (`remedy`: how to get it).
inline QString missingDataMessage(const QString& what, const QString& remedy) {
  return missingDataFails()
             ? what + QStringLiteral(", and CI=true makes that a failure, not a skip (") + remedy +
                   QLatin1Char(')')
             : what + QStringLiteral(" (") + remedy + QLatin1Char(')');
}

// The reference material: $LACRIMA_SHARED_DIR when set and not empty (ci_no_silent_skips points
// it at an empty folder), else the CMake cache variable of the same name.
inline QString sharedDir() {
  const QString fromEnvironment = qEnvironmentVariable("LACRIMA_SHARED_DIR");
  return fromEnvironment.isEmpty() ? QStringLiteral(LACRIMA_SHARED_DIR) : fromEnvironment;
}

inline QString sharedPath(const QString& relative) {
  return sharedDir() + QLatin1Char('/') + relative;
}

}  // namespace lacrima::testsupport

#define LACRIMA_SKIP_WITHOUT_DATA(what, remedy)                                                  \
  do {                                                                                           \
    const QString lacrimaWhyMissing_ = ::lacrima::testsupport::missingDataMessage(what, remedy); \
    if (::lacrima::testsupport::missingDataFails()) QFAIL(qPrintable(lacrimaWhyMissing_));       \
    QSKIP(qPrintable(lacrimaWhyMissing_));                                                       \
  } while (false)

#define LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD()                                                    \
  LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("the default head is not in the cache"),            \
                            QStringLiteral("bash packaging/fetch-default-head.sh fetches it; " \
                                           "when it could not, its output says why"))

// `path`: a file or folder of the reference material, from sharedPath().
#define LACRIMA_SKIP_WITHOUT_SHARED(path)                                              \
  LACRIMA_SKIP_WITHOUT_DATA(QStringLiteral("the reference material has no ") + (path), \
                            QStringLiteral("../shared, or $LACRIMA_SHARED_DIR"))

// Skips (fails under CI=true) unless `path` of the reference material exists.
#define LACRIMA_REQUIRE_SHARED(path)                                 \
  do {                                                               \
    if (!QFileInfo::exists(path)) LACRIMA_SKIP_WITHOUT_SHARED(path); \
  } while (false)
