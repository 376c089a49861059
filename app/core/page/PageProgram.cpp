#include "PageProgram.h"

#include "DrawBindings.h"

namespace phonglab {

namespace {

bool lights(const ProgramBindings &bindings)
{
    for (const BindingMeaning m :
         {BindingMeaning::LightPosition, BindingMeaning::LightPositionCamera,
          BindingMeaning::AmbientProduct, BindingMeaning::DiffuseProduct, BindingMeaning::Kd,
          BindingMeaning::Shininess, BindingMeaning::LightDiffuse, BindingMeaning::LightColor})
        if (!bindings.bound(m).empty())
            return true;
    return false;
}

} // namespace

std::optional<PageProgram> litPageProgram(const PageCapture &capture)
{
    std::optional<PageProgram> best;
    for (const CapturedOp *draw : capture.draws()) {
        const CapturedProgram *program = capture.program(draw->program);
        const ProgramBindings bindings = drawBindings(*draw);
        if (!program || !lights(bindings))
            continue;
        if (best && best->draw->count >= draw->count)
            continue;
        PageProgram chosen{program, draw, {}};
        for (const VariableBinding &b : bindings.variables)
            if (!b.meaning && !b.variable.isInput)
                if (const CapturedUniform *u = draw->uniform(b.variable.name); u && !u->isArray
                    && glslTypeOfGlEnum(u->glType) != GlslType::Other && !u->values.empty()
                    && !u->values.front().empty())
                    chosen.constants[u->name] = u->values.front();
        best = std::move(chosen);
    }
    return best;
}

const ProjectShader *stageInProject(const Project &project, ShaderStage stage,
                                    const QString &compiled)
{
    const QByteArray text = compiled.toUtf8().trimmed();
    for (const ProjectProgram &p : project.programs)
        for (const ProjectShader *s : {&p.vertex, &p.fragment})
            if (s->stage == stage && s->text.trimmed() == text)
                return s;
    return nullptr;
}

QString stageLocatorInProject(const Project &project, ShaderStage stage, const QString &compiled)
{
    const ProjectShader *shader = stageInProject(project, stage, compiled);
    return shader ? shaderLocator(*shader) : QString();
}

} // namespace phonglab
