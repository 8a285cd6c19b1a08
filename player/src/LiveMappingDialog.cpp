#include <lacrima/player/LiveMappingDialog.h>

#include <lacrima/common/FapTable.h>

#include <QDialogButtonBox>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lacrima::player {

LiveMappingDialog::LiveMappingDialog(const LiveLinkMapping& mapping, QWidget* parent)
    : QDialog(parent) {
  setWindowTitle(tr("Live Link mapping"));
  setObjectName("liveMappingDialog");
  auto* column = new QVBoxLayout(this);
  auto* about = new QLabel(
      tr("Each row adds gain x value to a FAP. Blendshapes are 0 to 1, angles in radians; gains "
         "in the FAP's units (docs/live.md). Apply takes effect with the next packet."),
      this);
  about->setWordWrap(true);
  column->addWidget(about);
  table_ = new QTableWidget(0, 3, this);
  table_->setHorizontalHeaderLabels({tr("Live Link value"), tr("FAP"), tr("Gain")});
  table_->horizontalHeader()->setStretchLastSection(true);
  table_->verticalHeader()->setVisible(false);
  column->addWidget(table_, 1);
  auto* buttons = new QDialogButtonBox(this);
  QPushButton* load = buttons->addButton(tr("&Load..."), QDialogButtonBox::ActionRole);
  QPushButton* save = buttons->addButton(tr("&Save as..."), QDialogButtonBox::ActionRole);
  QPushButton* apply = buttons->addButton(QDialogButtonBox::Apply);
  buttons->addButton(QDialogButtonBox::Close);
  connect(load, &QPushButton::clicked, this, &LiveMappingDialog::load);
  connect(save, &QPushButton::clicked, this, &LiveMappingDialog::saveAs);
  connect(apply, &QPushButton::clicked, this, [this] { emit applied(this->mapping()); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  column->addWidget(buttons);
  setMapping(mapping);
  resize(520, 640);
}

void LiveMappingDialog::setMapping(const LiveLinkMapping& mapping) {
  rows_ = mapping;
  table_->setRowCount(static_cast<int>(mapping.rows.size()));
  for (int r = 0; r < table_->rowCount(); ++r) {
    const LiveLinkMappingRow& row = mapping.rows[static_cast<std::size_t>(r)];
    auto* from = new QTableWidgetItem(
        QString::fromUtf8(liveLinkValueNames()[static_cast<std::size_t>(row.value)].data()));
    auto* to = new QTableWidgetItem(QString::fromUtf8(fapInfo(row.channel).name.data()));
    auto* gain = new QTableWidgetItem;
    gain->setData(Qt::EditRole, row.gain);  // edited as a number
    for (QTableWidgetItem* fixed : {from, to})
      fixed->setFlags(fixed->flags() & ~Qt::ItemIsEditable);
    table_->setItem(r, 0, from);
    table_->setItem(r, 1, to);
    table_->setItem(r, 2, gain);
  }
}

LiveLinkMapping LiveMappingDialog::mapping() const {
  LiveLinkMapping edited = rows_;
  for (int r = 0; r < table_->rowCount(); ++r) {
    const double gain = table_->item(r, 2)->data(Qt::EditRole).toDouble();
    edited.rows[static_cast<std::size_t>(r)].gain =
        std::isfinite(gain)
            ? std::clamp(gain, -LiveLinkMapping::kMaxGain, LiveLinkMapping::kMaxGain)
            : 0.0;
  }
  return edited;
}

void LiveMappingDialog::load() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Load a Live Link mapping"), {},
                                                    tr("Mappings (*.json);;All files (*)"));
  if (path.isEmpty()) return;
  try {
    setMapping(LiveLinkMapping::load(path.toStdString()));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Cannot load the mapping"), QString::fromUtf8(e.what()));
  }
}

void LiveMappingDialog::saveAs() {
  const QString path = QFileDialog::getSaveFileName(this, tr("Save the Live Link mapping"),
                                                    QStringLiteral("livelink-mapping.json"),
                                                    tr("Mappings (*.json)"));
  if (path.isEmpty()) return;
  try {
    mapping().save(path.toStdString());
  } catch (const std::exception& e) {
    QMessageBox::warning(this, tr("Cannot save the mapping"), QString::fromUtf8(e.what()));
  }
}

}  // namespace lacrima::player
