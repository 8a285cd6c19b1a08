// --threads as both programs read it: a whole number from 1 to 256, 0 when absent (the
// simulation then takes LACRIMA_THREADS, else every hardware thread), anything else a usage
// error naming the option. The editor is run as a process to show that it is its exit status
// 2 there (the player's is checked by test_player_render_cli).
#include <lacrima/appsupport/ThreadsOption.h>

#include <QCommandLineParser>
#include <QProcess>
#include <QtTest>

using namespace lacrima;

namespace {

constexpr int kRefused = -1;

int parse(const QStringList& arguments) {
  QCommandLineParser parser;
  parser.addOption(appsupport::threadsOption(QStringLiteral("the tear simulation")));
  if (!parser.parse(QStringList{QStringLiteral("program")} + arguments)) return kRefused;
  return appsupport::threadsFrom(parser, "program").value_or(kRefused);
}

}  // namespace

class ThreadsOptionTest : public QObject {
  Q_OBJECT

 private slots:
  void countsFromOneTo256() {
    QCOMPARE(parse({}), 0);
    QCOMPARE(parse({"--threads", "1"}), 1);
    QCOMPARE(parse({"--threads", "3"}), 3);
    QCOMPARE(parse({"--threads", "256"}), 256);
  }

  void anythingElseIsRefused() {
    for (const char* text : {"0", "257", "-2", "x", "2.5", ""})
      QVERIFY2(parse({"--threads", text}) == kRefused, text);
  }

  void editorSaysSoAndExitsWithUsage() {
    for (const char* text : {"0", "x"}) {
      QProcess editor;
      QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
      environment.insert("QT_QPA_PLATFORM", "offscreen");
      editor.setProcessEnvironment(environment);
      editor.start(QStringLiteral(LACRIMA_BIN_DIR "/lacrima-editor"), {"--threads", text});
      if (!editor.waitForFinished(60000)) {
        editor.kill();
        editor.waitForFinished();
        QFAIL("lacrima-editor --threads did not stop");
      }
      QCOMPARE(editor.exitStatus(), QProcess::NormalExit);
      QCOMPARE(editor.exitCode(), 2);
      const QString err = QString::fromLocal8Bit(editor.readAllStandardError());
      QVERIFY2(err.contains("--threads: expected threads from 1 to 256"), qPrintable(err));
    }
  }
};

QTEST_GUILESS_MAIN(ThreadsOptionTest)
#include "ThreadsOptionTest.moc"
