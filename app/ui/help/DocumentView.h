#pragma once
#include <QTextBrowser>

namespace phonglab {

// The page of the documentation browser: a QTextBrowser whose images are
// scaled down to a reading width. The screenshots and charts in docs/images
// are up to 2560 pixels wide, which would push the text off the side.
class DocumentView : public QTextBrowser
{
    Q_OBJECT

public:
    static constexpr int kMaxImageWidth = 760; // pixels

    explicit DocumentView(QWidget *parent = nullptr);

    QVariant loadResource(int type, const QUrl &name) override;
};

} // namespace phonglab
