#pragma once
#include <QFont>
#include <qpa/qplatformtheme.h>

namespace phonglab::headless {

// Fusion and the usual fonts: widgets drawn into images (the bench's charts)
// look as they do on a desktop without its platform theme.
class HeadlessTheme : public QPlatformTheme
{
public:
    QVariant themeHint(ThemeHint hint) const override
    {
        if (hint == StyleNames)
            return QStringList{QStringLiteral("Fusion")};
        return QPlatformTheme::themeHint(hint);
    }
    const QFont *font(Font type) const override
    {
        if (type == SystemFont)
            return &m_system;
        if (type == FixedFont)
            return &m_fixed;
        return nullptr;
    }

private:
    QFont m_system{QStringLiteral("Sans Serif"), 9};
    QFont m_fixed{QStringLiteral("monospace"), 9};
};

} // namespace phonglab::headless
