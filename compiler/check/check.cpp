// The checker's entry point, its scopes and name resolution, and imports.
#include "compiler/check/check.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "compiler/check/checkers.h"
#include "lang/syntax/parser.h"

namespace sled::compiler {

CheckedScenario ParseAndCheck(lang::SourceManager& sources, lang::FileId file,
                              const CheckOptions& options) {
  lang::ParseOptions parse_options;
  parse_options.diagnostics = options.diagnostics;
  const lang::ast::File ast = lang::Parse(sources, file, parse_options);
  return Check(sources, ast, options);
}

CheckedScenario Check(lang::SourceManager& sources, const lang::ast::File& file,
                      const CheckOptions& options) {
  if (!options.diagnostics) throw std::logic_error("compiler::Check: options.diagnostics is null");
  internal::Checker checker(sources, options);
  return checker.Run(file);
}

namespace internal {
namespace {

const std::vector<std::pair<EntityKind, std::string_view>> kEntityNames = {
    {EntityKind::kGround, "ground"},     {EntityKind::kModule, "module"},
    {EntityKind::kBody, "body"},         {EntityKind::kSegment, "segment"},
    {EntityKind::kJoint, "joint"},       {EntityKind::kEllipsoid, "ellipsoid"},
    {EntityKind::kVehicle, "vehicle"},   {EntityKind::kPlane, "plane"},
    {EntityKind::kFunction, "function"}, {EntityKind::kBelt, "belt"},
    {EntityKind::kHarness, "harness"},   {EntityKind::kAirbag, "airbag"},
    {EntityKind::kSpring, "spring"},     {EntityKind::kConstraint, "constraint"},
    {EntityKind::kLoad, "load"},         {EntityKind::kParameter, "parameter"},
    {EntityKind::kActuator, "actuator"},
};

std::string JoinPath(const std::vector<std::string>& parts, std::size_t from, char separator) {
  std::string out;
  for (std::size_t i = from; i < parts.size(); ++i) {
    if (!out.empty()) out += separator;
    out += parts[i];
  }
  return out;
}

// Module names available under a folder, as dotted paths, for "did you mean" on imports.
std::vector<std::string> ModulesUnder(const std::string& root, const std::string& prefix) {
  std::vector<std::string> names;
  std::error_code error;
  for (auto it = std::filesystem::recursive_directory_iterator(root, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    if (it->path().extension() != ".sled") continue;
    std::string relative = std::filesystem::relative(it->path(), root, error).string();
    relative = relative.substr(0, relative.size() - 5);
    std::replace(relative.begin(), relative.end(), '/', '.');
    names.push_back(prefix + relative);
  }
  std::sort(names.begin(), names.end());  // directory order differs between file systems
  return names;
}

// "Did you mean" for an import, or else the modules there are (a few of them).
std::string ModuleHelp(const std::string& wanted, const std::vector<std::string>& modules) {
  std::string help = lang::DidYouMean(wanted, modules);
  if (!help.empty()) return help;
  if (modules.empty()) {
    return "`import std.a.b` reads stdlib/a/b.sled; `import a.b` reads a/b.sled next to the scene";
  }
  constexpr std::size_t kListed = 6;
  std::string listed;
  for (std::size_t i = 0; i < std::min(modules.size(), kListed); ++i) {
    listed += (i > 0 ? ", `" : "`") + modules[i] + "`";
  }
  return fmt::format("modules here: {}{}", listed, modules.size() > kListed ? ", ..." : "");
}

}  // namespace

std::string_view EntityKindName(EntityKind kind) {
  for (const auto& [entity_kind, name] : kEntityNames) {
    if (entity_kind == kind) return name;
  }
  return "name";
}

std::optional<EntityKind> EntityKindFromName(std::string_view name) {
  for (const auto& [entity_kind, entity_name] : kEntityNames) {
    if (entity_name == name) return entity_kind;
  }
  return std::nullopt;
}

CheckContext::CheckContext(lang::SourceManager& sources, const CheckOptions& options)
    : sources_(sources), options_(options), dedupe_(*options.diagnostics), diagnostics_(dedupe_) {}

void CheckContext::DedupingConsumer::Consume(lang::Diagnostic diagnostic) {
  const lang::SourceRange* range = diagnostic.primary_range();
  auto key = std::make_tuple(range ? range->file.value : 0u, range ? range->begin : 0u,
                             diagnostic.message);
  if (!seen_.insert(std::move(key)).second) return;
  next_.Consume(std::move(diagnostic));
}

void CheckContext::Report(DiagnosticKind kind, SourceRange range, std::string message,
                          std::string label, std::string help) {
  auto diagnostic = lang::MakeDiagnostic(kind, range, std::move(message), std::move(label));
  diagnostic.help = std::move(help);
  diagnostics_.Consume(std::move(diagnostic));
}

Scope* CheckContext::NewScope(Scope* parent, std::string prefix, std::string directory) {
  auto scope = std::make_unique<Scope>();
  scope->parent = parent;
  scope->prefix = std::move(prefix);
  scope->directory = std::move(directory);
  scopes_.push_back(std::move(scope));
  return scopes_.back().get();
}

void CheckContext::RecordReference(SourceRange use, const Entity& entity, std::string name,
                                   bool is_declaration) {
  NameReference reference;
  reference.use = use;
  reference.declaration = entity.range;
  reference.name = std::move(name);
  reference.kind = std::string(EntityKindName(entity.kind));
  reference.is_declaration = is_declaration;
  if (entity.kind == EntityKind::kParameter) {
    // Its value is known only once every parameter is evaluated: filled in at the end of Run.
    parameter_references_.emplace_back(scenario_.references.size(), entity.index);
  } else {
    reference.index = entity.index;
  }
  scenario_.references.push_back(std::move(reference));
}

bool CheckContext::Declare(Scope& scope, const std::string& name, Entity entity) {
  auto [it, inserted] = scope.names.emplace(name, entity);
  if (entity.range.valid()) RecordReference(entity.range, entity, scope.prefix + name, true);
  if (!inserted) {
    auto diagnostic = lang::MakeDiagnostic(
        DiagnosticKind::kDuplicateName, entity.range,
        fmt::format("`{}` is declared twice", scope.prefix + name), "declared again here");
    diagnostic.labels.push_back({it->second.range, "first declared here", false});
    diagnostic.help = "names must be unique in a body, a module or a scenario; rename one";
    diagnostics_.Consume(std::move(diagnostic));
    return false;
  }
  return true;
}

std::vector<std::string> CheckContext::NamesOfKinds(Scope& scope,
                                                    const std::vector<EntityKind>& kinds) {
  auto wanted = [&](EntityKind kind) {
    return kinds.empty() || std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
  };
  std::vector<std::string> names;
  for (Scope* s = &scope; s; s = s->parent) {
    for (const auto& [name, entity] : s->names) {
      if (wanted(entity.kind)) names.push_back(name);
      for (Scope* inner = entity.inner; inner; inner = inner->fallback) {
        for (const auto& [inner_name, inner_entity] : inner->names) {
          if (wanted(inner_entity.kind)) names.push_back(fmt::format("{}.{}", name, inner_name));
        }
      }
    }
  }
  return names;
}

Entity* CheckContext::Resolve(Scope& scope, const ast::Expr& path,
                              const std::vector<EntityKind>& kinds, bool quiet) {
  const std::string kind_text =
      kinds.size() == 1 ? std::string(EntityKindName(kinds[0])) : std::string("name");
  if (path.kind != ast::ExprKind::kPath) {
    if (!quiet) {
      Report(DiagnosticKind::kWrongValueKind, path.range,
             fmt::format("expected the name of a {}, found {}", kind_text,
                         path.kind == ast::ExprKind::kNumber   ? "a number"
                         : path.kind == ast::ExprKind::kVector ? "a vector"
                         : path.kind == ast::ExprKind::kString ? "a string"
                                                               : "an expression"),
             "not a name", "a name is written without quotes or a unit, such as `occupant.pelvis`");
    }
    return nullptr;
  }
  Entity* found = nullptr;
  for (Scope* s = &scope; s && !found; s = s->parent) {
    auto it = s->names.find(path.path[0]);
    if (it != s->names.end()) found = &it->second;
  }
  for (std::size_t i = 1; found && i < path.path.size(); ++i) {
    Entity* next = nullptr;
    for (Scope* inner = found->inner; inner && !next; inner = inner->fallback) {
      auto it = inner->names.find(path.path[i]);
      if (it != inner->names.end()) next = &it->second;
    }
    found = next;
  }
  if (!found) {
    if (!quiet) {
      const std::string text = path.PathText();
      std::string help = lang::DidYouMean(text, NamesOfKinds(scope, kinds));
      if (help.empty()) {
        help =
            "declare it, or check the spelling; a name inside a body or import is written "
            "with its path, such as `occupant.pelvis`";
      }
      Report(DiagnosticKind::kUnknownName, path.range,
             fmt::format("unknown {} `{}`", kind_text, text),
             fmt::format("no {} named `{}`", kind_text, text), std::move(help));
    }
    return nullptr;
  }
  found->used = true;
  if (found->range.valid()) RecordReference(path.range, *found, path.PathText(), false);
  if (!kinds.empty() && std::find(kinds.begin(), kinds.end(), found->kind) == kinds.end()) {
    if (!quiet) {
      std::string expected;
      for (std::size_t i = 0; i < kinds.size(); ++i) {
        if (i > 0) expected += i + 1 == kinds.size() ? " or " : ", ";
        expected += EntityKindName(kinds[i]);
      }
      auto diagnostic =
          lang::MakeDiagnostic(DiagnosticKind::kWrongKindOfName, path.range,
                               fmt::format("`{}` is a {}, but a {} belongs here", path.PathText(),
                                           EntityKindName(found->kind), expected),
                               fmt::format("this is a {}", EntityKindName(found->kind)));
      if (found->range.valid()) {
        diagnostic.labels.push_back({found->range, "declared here", false});
      }
      // A segment where a joint belongs, or the other way round: the ones it is attached to,
      // not the names that happen to be spelt alike (`nij(occupant.head)` is not `hip_l`).
      diagnostic.help = AttachedNames(*found, kinds);
      if (diagnostic.help.empty()) {
        diagnostic.help = lang::DidYouMean(path.PathText(), NamesOfKinds(scope, kinds));
      }
      if (diagnostic.help.empty()) diagnostic.help = fmt::format("name a {} here", expected);
      diagnostics_.Consume(std::move(diagnostic));
    }
    return nullptr;
  }
  return found;
}

std::string CheckContext::AttachedNames(const Entity& found, const std::vector<EntityKind>& kinds) {
  auto wanted = [&](EntityKind kind) {
    return std::find(kinds.begin(), kinds.end(), kind) != kinds.end();
  };
  const auto index = found.index;
  if (found.kind == EntityKind::kSegment && wanted(EntityKind::kJoint) && index >= 0) {
    const std::string& segment = scenario_.segments[static_cast<std::size_t>(index)].name;
    auto name_of = [&](int s) {
      return s >= 0 ? scenario_.segments[static_cast<std::size_t>(s)].name : std::string("?");
    };
    std::vector<std::string> joints;  // the joint above the segment first
    const Joint* only = nullptr;
    for (const bool above : {true, false}) {
      for (const Joint& joint : scenario_.joints) {
        if ((above ? joint.child : joint.parent) == index && joint.type != JointType::kNull) {
          joints.push_back(fmt::format("`{}` ({} `{}`)", joint.name, above ? "from" : "to",
                                       name_of(above ? joint.parent : joint.child)));
          only = &joint;
        }
      }
    }
    if (joints.empty()) return "";
    if (joints.size() == 1) {
      return fmt::format("did you mean `{}`, the joint from `{}` to `{}`?", only->name,
                         name_of(only->parent), name_of(only->child));
    }
    std::string list;
    for (std::size_t i = 0; i < joints.size(); ++i) {
      list += (i == 0 ? "" : i + 1 == joints.size() ? " and " : ", ") + joints[i];
    }
    return fmt::format("the joints of `{}` are {}", segment, list);
  }
  if (found.kind == EntityKind::kJoint && wanted(EntityKind::kSegment) && index >= 0) {
    const Joint& joint = scenario_.joints[static_cast<std::size_t>(index)];
    if (joint.child < 0) return "";
    const std::string& child = scenario_.segments[static_cast<std::size_t>(joint.child)].name;
    if (joint.parent < 0) return fmt::format("did you mean `{}`, the segment it moves?", child);
    return fmt::format("did you mean `{}` or `{}`, the segments it joins?", child,
                       scenario_.segments[static_cast<std::size_t>(joint.parent)].name);
  }
  return "";
}

void SceneChecker::Import(Scope& scope, const ast::Statement& statement) {
  if (!statement.target || statement.target->kind != ast::ExprKind::kPath || statement.has_value ||
      statement.block) {
    Report(DiagnosticKind::kMalformedStatement, statement.range,
           "an import names a module: `import std.humans.male50 as occupant`", "not an import",
           "give the module's dotted path after `import`; `as NAME` names it here");
    return;
  }
  const std::vector<std::string>& parts = statement.target->path;
  std::string alias = parts.back();
  if (const ast::Clause* as = statement.FindClause("as")) {
    if (as->value.kind != ast::ExprKind::kPath || as->value.path.size() != 1) {
      Report(DiagnosticKind::kMalformedStatement, as->value.range, "`as` takes one plain name",
             "not a plain name", "the alias is one word without dots, such as `occupant`");
      return;
    }
    alias = as->value.path[0];
  }
  const ast::Clause* on = statement.FindClause("on");
  for (const ast::Clause& clause : statement.clauses) {
    if (clause.word != "as" && clause.word != "on") {
      Report(DiagnosticKind::kMalformedStatement, clause.word_range,
             fmt::format("an import takes no `{}` clause", clause.word), "not allowed here",
             "an import takes only `as NAME`");
    }
  }

  const bool standard = parts[0] == "std";
  const std::string relative = JoinPath(parts, standard ? 1 : 0, '/');
  // `std.x` is in the standard library; another module in the importing file's folder, else in
  // the first folder of the module path that has it.
  std::vector<std::string> roots;
  if (standard) {
    roots.push_back(options_.stdlib_root.empty() ? DefaultStdlibRoot() : options_.stdlib_root);
  } else {
    roots.push_back(scope.directory);
    roots.insert(roots.end(), options_.module_path.begin(), options_.module_path.end());
  }
  auto path_under = [&](const std::string& folder) {
    return (folder.empty() ? std::string(".") : folder) + "/" + relative + ".sled";
  };
  std::string root = roots.front();
  for (const std::string& candidate : roots) {
    std::error_code error;
    if (sources_.Find(path_under(candidate)) ||
        std::filesystem::is_regular_file(path_under(candidate), error)) {
      root = candidate;
      break;
    }
  }
  const std::string file_path = path_under(root);

  if (std::find(import_stack_.begin(), import_stack_.end(), file_path) != import_stack_.end()) {
    Report(DiagnosticKind::kImportCycle, statement.target->range,
           fmt::format("module `{}` imports itself through a cycle", statement.target->PathText()),
           "this import closes the cycle",
           "move what both modules need into a third module that neither imports");
    return;
  }

  Scope* module_scope = nullptr;
  auto cached = module_scopes_.find(file_path);
  if (cached != module_scopes_.end()) {
    module_scope = cached->second;
  } else {
    std::optional<lang::FileId> id = sources_.Find(file_path);
    if (!id) id = sources_.Load(file_path);
    if (!id || (!standard && relative.empty())) {
      Report(DiagnosticKind::kUnknownModule, statement.target->range,
             fmt::format("no module `{}`", statement.target->PathText()),
             fmt::format("`{}` does not exist", file_path),
             ModuleHelp(statement.target->PathText(),
                        standard ? ModulesUnder(root, "std.") : ModulesUnder(root, "")));
      return;
    }
    lang::ParseOptions parse_options;
    parse_options.diagnostics = &diagnostics_;
    modules_.push_back(std::make_unique<ast::File>(lang::Parse(sources_, *id, parse_options)));
    const ast::File& module = *modules_.back();
    module_scope = NewScope(nullptr, "", std::filesystem::path(file_path).parent_path().string());
    module_scopes_[file_path] = module_scope;
    import_stack_.push_back(file_path);
    DeclareFileContents(*module_scope, module.body, BlockKind::kModule);
    import_stack_.pop_back();
  }

  // A module with exactly one body is that body: its alias names the instance.
  std::vector<const ast::Statement*> bodies;
  const ast::File* module_file = nullptr;
  for (const auto& module : modules_) {
    if (sources_.buffer(module->file).path() == file_path) module_file = module.get();
  }
  if (module_file) {
    for (const ast::Statement& child : module_file->body.statements) {
      if (child.keyword == "body" && child.kind == ast::StatementKind::kHeader) {
        bodies.push_back(&child);
      }
    }
  }
  const std::string qualified = scope.prefix + alias;
  // The module's planes and ellipsoids are instanced with the alias, fixed in the frame of the
  // import's `on` clause (the ground without one).
  auto instance_surfaces = [&](Scope& instance) {
    if (module_file) {
      DeclareModuleSurfaces(instance, module_file->body, on ? &on->value : nullptr, scope);
    }
  };
  if (bodies.size() == 1) {
    const int index = static_cast<int>(scenario_.bodies.size());
    CheckBodyDeclarations(*module_scope, *bodies[0], qualified, statement.range);
    Scope* body_scope = bodies_.back().scope;
    body_scope->fallback = module_scope;
    Declare(scope, alias, Entity{EntityKind::kBody, index, statement.range, body_scope});
    instance_surfaces(*body_scope);
    return;
  }
  // Otherwise the alias is a namespace; each body is instanced under alias.body. Plain names in
  // the module's surfaces resolve in the module.
  Scope* instance_scope = NewScope(module_scope, qualified + ".", module_scope->directory);
  instance_scope->fallback = module_scope;
  instance_surfaces(*instance_scope);
  for (const ast::Statement* body : bodies) {
    if (!body->target || body->target->kind != ast::ExprKind::kPath) continue;
    const std::string& body_name = body->target->path[0];
    const int index = static_cast<int>(scenario_.bodies.size());
    CheckBodyDeclarations(*module_scope, *body, fmt::format("{}.{}", qualified, body_name),
                          statement.range);
    Declare(*instance_scope, body_name,
            Entity{EntityKind::kBody, index, body->range, bodies_.back().scope});
  }
  Declare(scope, alias, Entity{EntityKind::kModule, -1, statement.range, instance_scope});
}

CheckedScenario Checker::Run(const ast::File& file) {
  const std::string directory =
      std::filesystem::path(sources_.buffer(file.file).path()).parent_path().string();
  scene_scope_ = NewScope(nullptr, "", directory);
  for (const auto& [name, text] : options_.overrides) {
    const lang::FileId id = sources_.Add(fmt::format("--set {}", name), text);
    lang::ParseOptions parse_options;
    parse_options.diagnostics = &diagnostics_;
    Override entry{name,
                   lang::ParseValue(sources_, id, parse_options),
                   {id, 0, static_cast<std::uint32_t>(text.size())}};
    overrides_.push_back(std::move(entry));
  }
  Declare(*scene_scope_, "ground", Entity{EntityKind::kGround, -1, {}, nullptr, true});
  import_stack_.push_back(sources_.buffer(file.file).path());

  // A file with a scenario is a scene; one without is a module, checked body by body.
  bool has_scenario = false;
  for (const ast::Statement& statement : file.body.statements) {
    has_scenario |= statement.keyword == "scenario";
  }
  DeclareFileContents(*scene_scope_, file.body,
                      has_scenario ? BlockKind::kFile : BlockKind::kModule);
  if (!has_scenario) {
    // A module offers what scenes may use: its surfaces are checked in the ground frame, and
    // nothing is reported as unused.
    checking_module_ = true;
    DeclareModuleSurfaces(*scene_scope_, file.body, nullptr, *scene_scope_);
    // Each body of a module is checked as an instance under its own name.
    for (const ast::Statement& statement : file.body.statements) {
      if (statement.keyword != "body" || !statement.target ||
          statement.target->kind != ast::ExprKind::kPath) {
        continue;
      }
      const int index = static_cast<int>(scenario_.bodies.size());
      const std::string& name = statement.target->path[0];
      CheckBodyDeclarations(*scene_scope_, statement, name, statement.range);
      Declare(
          *scene_scope_, name,
          Entity{EntityKind::kBody, index, statement.target->range, bodies_.back().scope, true});
    }
  }

  for (const Override& entry : overrides_) {
    if (entry.used || !entry.value) continue;
    std::vector<std::string> names;
    for (const auto& parameter : parameters_) {
      if (parameter->is_param && parameter->scope == scene_scope_) names.push_back(parameter->name);
    }
    Report(DiagnosticKind::kUnknownOverride, entry.range,
           fmt::format("`--set {}` names no `param` of the scenario", entry.name),
           "no such parameter",
           lang::DidYouMean(entry.name, names).empty()
               ? "only `param` declarations of the scenario can be set"
               : lang::DidYouMean(entry.name, names));
  }

  // Every name is known now: check what the declarations say.
  EvaluateParameters();
  for (const auto& parameter : parameters_) {
    if (!parameter->is_param || parameter->scope != scene_scope_) continue;
    const bool valid = parameter->state == Parameter::State::kDone;
    scenario_.parameters.push_back({parameter->name, parameter->value.components,
                                    parameter->value.dimension, parameter->value.bare, valid,
                                    parameter->range});
  }
  defining_functions_ = true;
  for (const Pending& pending : functions_) {
    DefineFunction(*pending.scope, *pending.statement, pending.index);
  }
  defining_functions_ = false;
  ResolvePendingAtbLaws();
  CheckBodyDetails();
  CheckSceneElements();
  CheckContacts();
  CheckRestraints();
  CheckLoads();
  CheckActuators();
  scenario_.has_scenario = scenario_statement_ != nullptr;
  if (scenario_statement_) CheckRunSettings(*scene_scope_, scenario_bound_);
  if (scenario_statement_) CheckFluids(*scene_scope_);
  CheckInitialConditions();
  CheckWelds();
  CheckHeldInitialConditions();
  CheckLoadsInThePlane();
  CheckOutputs();
  CheckDuplicates();
  CheckElementLaws();
  if (options_.lints) RunLints();
  for (const auto& [reference, parameter_index] : parameter_references_) {
    const Parameter& parameter = *parameters_.at(static_cast<std::size_t>(parameter_index));
    if (parameter.state != Parameter::State::kDone) continue;
    scenario_.references[reference].value = parameter.value.components;
    scenario_.references[reference].dimension = parameter.value.dimension;
  }
  return std::move(scenario_);
}

}  // namespace internal
}  // namespace sled::compiler
