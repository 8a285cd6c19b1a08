#pragma once
// Live > Live Link mapping...: the table from Live Link Face values to FAPs (LiveLinkMapping.h,
// docs/live.md), one row per line with its gain editable. Apply hands the edited table to the
// inputs at once (the face follows the new gains with the next packet); Save as... writes it
// (atomically) for --mapping FILE or a later Load...
#include <lacrima/common/LiveLinkMapping.h>

#include <QDialog>

class QTableWidget;

namespace lacrima::player {

class LiveMappingDialog : public QDialog {
  Q_OBJECT
 public:
  explicit LiveMappingDialog(const LiveLinkMapping& mapping, QWidget* parent = nullptr);

  // The table with the gains as edited.
  LiveLinkMapping mapping() const;
  void setMapping(const LiveLinkMapping& mapping);
  QTableWidget& table() { return *table_; }

 signals:
  void applied(const LiveLinkMapping& mapping);

 private:
  void load();
  void saveAs();

  LiveLinkMapping rows_;
  QTableWidget* table_;
};

}  // namespace lacrima::player
