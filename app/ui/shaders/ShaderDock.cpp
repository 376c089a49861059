#include "ShaderDock.h"

#include "core/project/ProjectShader.h"

#include "DiagnosticList.h"
#include "ShaderEditor.h"
#include "ShaderFileSet.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QToolBar>
#include <QToolButton>
#include <QVBoxLayout>
#include <optional>
#include <utility>

namespace phonglab {

namespace {
// The box's entry for the student's own shaders (no method's name).
const QString kOwnShaders = QStringLiteral("own");
} // namespace

namespace {

std::optional<ShaderStage> stageFromSuffix(const QString &path)
{
    // A WebGL project's shader: its stage is its content's.
    if (isShaderLocator(path)) {
        const Result<ProjectShader> shader = shaderAtLocator(path);
        if (!shader)
            return std::nullopt;
        return shader->stage == ShaderStage::Vertex ? ShaderStage::Vertex : ShaderStage::Fragment;
    }
    return stageOfSuffix(path);
}

// "blinn-phong" -> "Blinn-Phong" for the shading method box.
QString displayName(const QString &name)
{
    QStringList parts = name.split(QLatin1Char('-'));
    for (QString &part : parts)
        if (!part.isEmpty())
            part[0] = part[0].toUpper();
    return parts.join(QLatin1Char('-'));
}

QString stageTitle(ShaderStage stage)
{
    return stage == ShaderStage::Vertex ? QObject::tr("Vertex") : QObject::tr("Fragment");
}

} // namespace

ShaderDock::ShaderDock(QWidget *parent)
    : QDockWidget(tr("Shaders"), parent)
    , m_vertex(new ShaderEditor)
    , m_fragment(new ShaderEditor)
    , m_tabs(new QTabWidget)
    , m_shadingMethods(new QComboBox)
    , m_status(new QLabel)
    , m_diagnostics(new DiagnosticList)
    , m_files(new ShaderFileSet(this))
{
    setObjectName(QStringLiteral("shaderDock")); // for QMainWindow::saveState
    m_vertex->setObjectName(QStringLiteral("vertexEditor"));
    m_fragment->setObjectName(QStringLiteral("fragmentEditor"));
    m_tabs->addTab(m_vertex, stageTitle(ShaderStage::Vertex));
    m_tabs->addTab(m_fragment, stageTitle(ShaderStage::Fragment));
    m_tabs->setCurrentWidget(m_fragment); // where most of the lighting lives
    m_tabs->setObjectName(QStringLiteral("shaderTabs"));
    m_shadingMethods->setObjectName(QStringLiteral("shadingMethodBox"));
    m_status->setObjectName(QStringLiteral("shaderStatus"));
    m_diagnostics->setObjectName(QStringLiteral("diagnosticList"));
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_status->setWordWrap(true);
    m_files->setDialogParent(this);

    auto *splitter = new QSplitter(Qt::Vertical);
    splitter->addWidget(m_tabs);
    splitter->addWidget(m_diagnostics);
    splitter->setStretchFactor(0, 4);
    splitter->setStretchFactor(1, 1);

    auto *contents = new QWidget;
    auto *layout = new QVBoxLayout(contents);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addWidget(createToolBar());
    layout->addWidget(splitter, 1);
    auto *statusRow = new QHBoxLayout;
    statusRow->addWidget(m_status, 1);
    m_applyAnyway = new QPushButton(tr("Apply anyway"), contents);
    m_applyAnyway->setObjectName(QStringLiteral("applyAnyway"));
    m_applyAnyway->setToolTip(
        tr("Draw with this program although its frames are slow; the view then draws only "
           "when you ask it to"));
    m_applyAnyway->hide();
    connect(m_applyAnyway, &QPushButton::clicked, this, &ShaderDock::applyAnywayRequested);
    statusRow->addWidget(m_applyAnyway, 0, Qt::AlignTop);
    // The row is as tall with the button as without: its showing must not
    // change the dock's height, which would resize and re-frame the view.
    m_status->setMinimumHeight(m_applyAnyway->sizeHint().height());
    layout->addLayout(statusRow);
    setWidget(contents);

    connectEditor(ShaderStage::Vertex);
    connectEditor(ShaderStage::Fragment);
    connectFiles();
    connect(m_diagnostics, &DiagnosticList::diagnosticActivated, this, &ShaderDock::goTo);
    updateTab(ShaderStage::Vertex);
    updateTab(ShaderStage::Fragment);
}

QWidget *ShaderDock::createToolBar()
{
    auto *bar = new QToolBar;
    bar->setIconSize(QSize(16, 16));
    for (const QString &name : shadingNames())
        m_shadingMethods->addItem(displayName(name), name);
    m_shadingMethods->setToolTip(tr("Load a shading method's shaders"));
    m_shadingMethods->setSizeAdjustPolicy(QComboBox::AdjustToContents); // a file's whole name
    connect(m_shadingMethods, &QComboBox::activated, this, [this](int index) {
        if (const auto method = shadingFromName(m_shadingMethods->itemData(index).toString()))
            emit shadingMethodRequested(*method);
    });
    bar->addWidget(m_shadingMethods);

    // The shortcut works wherever the focus is inside the dock, the editors
    // included (QScintilla does not bind F5).
    auto *compile = new QAction(style()->standardIcon(QStyle::SP_MediaPlay), tr("Compile"), this);
    compile->setObjectName(QStringLiteral("compileAction"));
    compile->setShortcut(QKeySequence(Qt::Key_F5));
    compile->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    compile->setToolTip(tr("Compile and link both stages (F5)"));
    connect(compile, &QAction::triggered, this, &ShaderDock::compileRequested);
    addAction(compile);
    bar->addAction(compile);
    if (auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(compile)))
        button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->addSeparator();

    // Open and Save have no shortcuts: Ctrl+O / Ctrl+S belong to the window's
    // scene commands, and the same keys in two contexts would be ambiguous.
    bar->addAction(style()->standardIcon(QStyle::SP_DialogOpenButton), tr("Open…"), this,
                   &ShaderDock::openRequested)
        ->setToolTip(tr("Open a shader, or a .vert/.frag pair"));
    bar->addAction(style()->standardIcon(QStyle::SP_DialogSaveButton), tr("Save"), this,
                   &ShaderDock::saveRequested)
        ->setToolTip(tr("Save the current tab (shipped shaders are saved as a user copy)"));
    bar->addAction(tr("Save As…"), this, &ShaderDock::saveAsRequested)
        ->setToolTip(tr("Save the current tab under another name"));
    return bar;
}

void ShaderDock::connectEditor(ShaderStage stage)
{
    ShaderEditor *e = editor(stage);
    connect(e, &QsciScintilla::textChanged, this, [this, stage] {
        if (!m_settingText)
            emit textEdited(stage);
    });
    connect(e, &QsciScintilla::modificationChanged, this, [this, stage](bool modified) {
        if (!m_settingText)
            m_files->setDirty(stage, modified);
    });
}

void ShaderDock::connectFiles()
{
    connect(m_files, &ShaderFileSet::pathChanged, this, [this](ShaderStage stage) {
        updateTab(stage);
        showWhoseShaders();
        if (!m_settingText)
            emit filesChanged();
    });
    connect(m_files, &ShaderFileSet::dirtyChanged, this, &ShaderDock::updateTab);
    connect(m_files, &ShaderFileSet::reloaded, this,
            [this](ShaderStage stage, const QByteArray &code) {
                setEditorCode(stage, code);
                emit textEdited(stage);
                emit filesChanged();
            });
    connect(m_files, &ShaderFileSet::problem, this, [this](const QString &message) {
        setCompileStatus(message, false); // not a dialog: this happens while typing
    });
}

void ShaderDock::setEditorCode(ShaderStage stage, const QByteArray &code)
{
    const bool wasSetting = std::exchange(m_settingText, true);
    editor(stage)->setCode(code);
    m_settingText = wasSetting;
}

void ShaderDock::setSources(const ShaderSource &vertex, const ShaderSource &fragment)
{
    const bool wasSetting = std::exchange(m_settingText, true);
    using Entry = std::pair<ShaderStage, const ShaderSource *>;
    for (const auto &[stage, source] :
         {Entry{ShaderStage::Vertex, &vertex}, Entry{ShaderStage::Fragment, &fragment}}) {
        editor(stage)->clearDiagnostics();
        editor(stage)->setCode(source->code);
        m_files->setFile(stage, source->name, source->code);
    }
    m_diagnostics->clear();
    m_settingText = wasSetting;
}

QByteArray ShaderDock::text(ShaderStage stage) const
{
    return editor(stage)->code();
}

QString ShaderDock::filePath(ShaderStage stage) const
{
    return m_files->path(stage);
}

bool ShaderDock::isDirty(ShaderStage stage) const
{
    return m_files->isDirty(stage);
}

bool ShaderDock::hasUnsavedChanges() const
{
    return isDirty(ShaderStage::Vertex) || isDirty(ShaderStage::Fragment);
}

ShaderEditor *ShaderDock::editor(ShaderStage stage) const
{
    return stage == ShaderStage::Vertex ? m_vertex : m_fragment;
}

ShaderStage ShaderDock::currentStage() const
{
    return m_tabs->currentWidget() == m_vertex ? ShaderStage::Vertex : ShaderStage::Fragment;
}

void ShaderDock::showDiagnostics(const std::vector<ShaderDiagnostic> &diagnostics)
{
    std::vector<ShaderDiagnostic> vertex;
    std::vector<ShaderDiagnostic> fragment;
    for (const ShaderDiagnostic &diagnostic : diagnostics) {
        if (diagnostic.step == BuildStep::CompileVertex)
            vertex.push_back(diagnostic);
        else if (diagnostic.step == BuildStep::CompileFragment || diagnostic.line > 0)
            fragment.push_back(diagnostic);
    }
    m_vertex->setDiagnostics(vertex);
    m_fragment->setDiagnostics(fragment);
    m_diagnostics->setDiagnostics(diagnostics);
}

void ShaderDock::showCheckMarks(const std::vector<ShaderDiagnostic> &vertex,
                                const QByteArray &vertexText,
                                const std::vector<ShaderDiagnostic> &fragment,
                                const QByteArray &fragmentText)
{
    m_vertex->setCheckMarks(m_vertex->code() == vertexText ? vertex
                                                           : std::vector<ShaderDiagnostic>{});
    m_fragment->setCheckMarks(m_fragment->code() == fragmentText ? fragment
                                                                 : std::vector<ShaderDiagnostic>{});
}

void ShaderDock::setCompileStatus(const QString &text, bool ok)
{
    m_applyAnyway->hide();
    m_status->setText(text);
    m_status->setStyleSheet(ok ? QStringLiteral("color: #2e7d32;")
                               : QStringLiteral("color: #c62828;"));
}

void ShaderDock::offerToApplyAnyway(const QString &text)
{
    setCompileStatus(text, false);
    m_applyAnyway->show();
}

// The box above the editor names what the editor holds: a shading
// method's shipped shaders, or the student's own by its file.
void ShaderDock::showWhoseShaders()
{
    const QString fragment = m_files->path(ShaderStage::Fragment);
    const QString vertex = m_files->path(ShaderStage::Vertex);
    const QString own = !fragment.isEmpty() && !m_files->isShipped(fragment) ? fragment
        : !vertex.isEmpty() && !m_files->isShipped(vertex)                   ? vertex
                                                                             : QString();
    const int ownIndex = m_shadingMethods->findData(kOwnShaders);
    if (own.isEmpty()) {
        if (ownIndex >= 0) {
            m_shadingMethods->removeItem(ownIndex);
            selectShadingMethod(m_method);
        }
        return;
    }
    const QString text = tr("%1 (your shader)").arg(QFileInfo(own).fileName());
    if (ownIndex >= 0)
        m_shadingMethods->setItemText(ownIndex, text);
    else
        m_shadingMethods->insertItem(0, text, kOwnShaders);
    m_shadingMethods->setCurrentIndex(m_shadingMethods->findData(kOwnShaders));
}

void ShaderDock::selectShadingMethod(ShadingMethod method)
{
    m_method = method;
    if (m_shadingMethods->findData(kOwnShaders) >= 0)
        return; // the box names the student's shaders, whatever method the scene says
    const int index = m_shadingMethods->findData(shadingName(method));
    if (index >= 0)
        m_shadingMethods->setCurrentIndex(index); // activated() is for the user's choices only
}

void ShaderDock::goTo(ShaderStage stage, int line, int column)
{
    ShaderEditor *target = editor(stage);
    m_tabs->setCurrentWidget(target);
    if (line > 0)
        target->goTo(line, column);
    else
        target->setFocus(Qt::OtherFocusReason);
}

Result<> ShaderDock::openFiles(const QStringList &paths)
{
    if (paths.isEmpty() || paths.size() > 2)
        return fail(tr("Open one shader, or a vertex and a fragment shader."));
    QList<std::pair<ShaderStage, ShaderSource>> opened;
    for (const QString &path : paths) {
        const auto stage = stageFromSuffix(path);
        if (!stage && paths.size() == 2)
            return fail(tr("%1: cannot tell which stage it is (use .vert or .frag)").arg(path));
        Result<ShaderSource> source = ShaderSource::forEditing(path);
        if (!source)
            return fail(source.error());
        opened.append({stage.value_or(currentStage()), *source});
    }
    if (opened.size() == 2 && opened[0].first == opened[1].first)
        return fail(tr("Both files are %1 shaders.").arg(stageName(opened[0].first)));
    showOpened(opened);
    return {};
}

Result<> ShaderDock::openFile(ShaderStage stage, const QString &path)
{
    Result<ShaderSource> source = ShaderSource::forEditing(path);
    if (!source)
        return fail(source.error());
    showOpened({{stage, *source}});
    return {};
}

void ShaderDock::showOpened(const QList<std::pair<ShaderStage, ShaderSource>> &opened)
{
    const bool wasSetting = std::exchange(m_settingText, true);
    for (const auto &[stage, source] : opened) {
        editor(stage)->clearDiagnostics();
        editor(stage)->setCode(source.code);
        m_files->setFile(stage,
                         isShaderLocator(source.name) ? source.name
                                                      : QFileInfo(source.name).absoluteFilePath(),
                         source.code);
    }
    m_settingText = wasSetting;
    m_tabs->setCurrentWidget(editor(opened.last().first));
    for (const auto &entry : opened)
        emit textEdited(entry.first);
    emit filesChanged();
}

Result<> ShaderDock::save(ShaderStage stage)
{
    Result<> saved = m_files->save(stage, text(stage));
    if (saved)
        editor(stage)->setModified(false); // the save point: undoing back to here is clean
    return saved;
}

Result<> ShaderDock::saveAs(ShaderStage stage, const QString &path)
{
    Result<> saved = m_files->saveAs(stage, path, text(stage));
    if (saved)
        editor(stage)->setModified(false);
    return saved;
}

void ShaderDock::updateTab(ShaderStage stage)
{
    const QString path = filePath(stage);
    const QString name = path.isEmpty() ? stageTitle(stage) : QFileInfo(path).fileName();
    const int index = m_tabs->indexOf(editor(stage));
    m_tabs->setTabText(index, isDirty(stage) ? name + QLatin1Char('*') : name);
    QString tip = tr("%1 shader").arg(stageTitle(stage));
    if (!path.isEmpty())
        tip += QStringLiteral(": ") + QDir::toNativeSeparators(path);
    if (m_files->isShipped(path))
        tip += tr("\nShipped with PhongLab: edits go to a user copy.");
    m_tabs->setTabToolTip(index, tip);
}

} // namespace phonglab
