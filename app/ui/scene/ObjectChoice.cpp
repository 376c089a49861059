#include "ObjectChoice.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFileInfo>

namespace phonglab {

void fillObjectChoice(QComboBox *combo, const Scene &scene)
{
    const int keep = combo->currentIndex();
    combo->clear();
    for (int i = 0; i < int(scene.objects.size()); ++i)
        combo->addItem(QCoreApplication::translate("ObjectChoice", "%1: %2")
                           .arg(i + 1)
                           .arg(QFileInfo(scene.objects[i].mesh).fileName()));
    combo->setCurrentIndex(keep >= 0 && keep < combo->count() ? keep : 0);
}

} // namespace phonglab
