// fcql_pymeshlab_host: runs MeshLab 2025.07 filters the way pymeshlab does, without Python.
//
// pymeshlab (PyMeshLab 2022.2 and later) is a thin pybind11 layer over MeshLab's own library:
// at import it loads the plugins of its plugin folder with meshlab::pluginManagerInstance(),
// lists them with pymeshlab::functionSetInstance() (python names from pythonFilterName() or
// computePythonName()), and MeshSet.apply_filter(name, **kwargs) looks the filter up by python
// name, builds its RichParameterList with initParameterList(), sets the keyword arguments by
// python parameter name, calls FilterPlugin::applyFilter() and turns the returned
// std::map<std::string, QVariant> into a dict. This program does the same steps with the same
// MeshLab calls and error messages (PyMeshLabException texts), so a filter plugin that works
// here works in pymeshlab; pymeshlab itself cannot be installed on this machine.
//
// Usage:
//   fcql_pymeshlab_host [--plugins DIR]... [--verbose] COMMAND...
// --plugins DIR loads every plugin of DIR, as pymeshlab loads its plugin folder (default: the
// SDK's io_base and the built libfilter_fieldquadlayout2025.so, FCQL_HOST_DEFAULT_PLUGIN_DIRS).
// Commands run in order, like the lines of a Python script on one MeshSet `ms`:
//   load_plugin FILE          pluginManagerInstance().loadPlugin(FILE): the loader's checks
//                             (Qt plugin, MeshLab plugin, float/double, version, filter checks)
//   filters                   the python filter names and parameters of the loaded plugins
//                             (pymeshlab.print_filter_list())
//   load FILE                 ms.load_new_mesh(FILE)
//   apply NAME [KEY=VALUE]... ms.apply_filter('NAME', KEY=VALUE, ...); prints the returned dict
//                             as a line "NAME -> {'key': value, ...}"
//   save FILE                 ms.save_current_mesh(FILE)
//   save_layer LABEL FILE     saves the mesh labelled LABEL (a layer a filter added)
//   info                      the meshes of the MeshSet: id, label, vertices, faces, edges
// Values: true/false (or True/False) for bools, integers, floats, anything else is a string.
// An error prints "PyMeshLabException: <message>" on stderr and exits with status 1, before
// the remaining commands. Run with QT_QPA_PLATFORM=offscreen (no X server is needed).

#include <common/globals.h>
#include <common/mlexception.h>
#include <common/ml_document/mesh_document.h>
#include <common/parameters/rich_parameter_list.h>
#include <common/plugins/plugin_manager.h>
#include <common/python/function_set.h>
#include <common/python/python_utils.h>
#include <common/utilities/load_save.h>

#include <vcg/complex/allocate.h>

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QStringList>

#include <clocale>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool verbose = false;

bool progress(const int, const char*) { return true; }

// ---- keyword arguments ----------------------------------------------------------------------

struct Kwarg {
  std::string key, value;
};

bool parseBool(const std::string& s, bool& out) {
  if (s == "true" || s == "True" || s == "1") return out = true, true;
  if (s == "false" || s == "False" || s == "0") return out = false, true;
  return false;
}

bool parseInt(const std::string& s, int& out) {
  std::istringstream in(s);
  long long v;
  if (!(in >> v) || !in.eof() || v < INT32_MIN || v > INT32_MAX) return false;
  out = int(v);
  return true;
}

bool parseFloat(const std::string& s, double& out) {
  std::istringstream in(s);
  in.imbue(std::locale::classic());
  if (!(in >> out) || !in.eof()) return false;
  return true;
}

// What pybind11 says when a Python value cannot be cast to the parameter's C++ type.
[[noreturn]] void castError(const RichParameter& par, const Kwarg& k, const char* type) {
  throw MLException("Parameter " + par.pythonName() + ": unable to cast '" +
                    QString::fromStdString(k.value) + "' to " + type);
}

// pymeshlab's meshsethelper::updateRichParameterFromKwarg, for the types a value given on the
// command line can have.
void setParameter(RichParameter& par, const Kwarg& k) {
  const QString type = par.stringType();
  if (par.isOfType<RichBool>()) {
    bool v;
    if (!parseBool(k.value, v)) castError(par, k, "bool");
    par.setValue(BoolValue(v));
  } else if (par.isOfType<RichInt>()) {
    int v;
    if (!parseInt(k.value, v)) castError(par, k, "int");
    par.setValue(IntValue(v));
  } else if (par.isOfType<RichDynamicFloat>()) {
    double v;
    if (!parseFloat(k.value, v)) castError(par, k, "float");
    const RichDynamicFloat& dyn = dynamic_cast<const RichDynamicFloat&>(par);
    float f = float(v);
    if (f < dyn.min) f = dyn.min;  // pymeshlab clamps bounded floats
    if (f > dyn.max) f = dyn.max;
    par.setValue(FloatValue(f));
  } else if (par.isOfType<RichFloat>() || par.isOfType<RichPercentage>()) {
    double v;
    if (!parseFloat(k.value, v)) castError(par, k, "float");
    par.setValue(FloatValue(float(v)));
  } else if (par.isOfType<RichString>()) {
    par.setValue(StringValue(QString::fromStdString(k.value)));
  } else {
    throw MLException("Parameter " + par.pythonName() + ": type " + type +
                      " cannot be given on this host's command line");
  }
}

// pymeshlab's meshsethelper::updateRichParameterListFromKwargs.
void setKwargs(const pymeshlab::Function& f, const std::vector<Kwarg>& kwargs,
               RichParameterList& rpl) {
  for (const Kwarg& k : kwargs) {
    const QString key = QString::fromStdString(k.key);
    if (f.contains(key)) {
      const pymeshlab::FunctionParameter& ffp = f.getFilterFunctionParameter(key);
      RichParameterList::iterator it = rpl.findParameter(ffp.meshlabName());
      if (it != rpl.end()) setParameter(*it, k);
      continue;
    }
    bool found = false;
    for (RichParameter& par : rpl)
      if (par.pythonName() == key) {
        setParameter(par, k);
        found = true;
        break;
      }
    if (!found)
      throw MLException("Parameter " + key + " not found for filter " + f.pythonFunctionName() +
                        ". Please check the documentation.");
  }
}

// ---- the returned dict ----------------------------------------------------------------------

// pymeshlab's toPyDict, printed as Python would print the dict.
std::string formatDict(const std::map<std::string, QVariant>& values) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "{";
  bool first = true;
  for (const auto& p : values) {
    out << (first ? "" : ", ") << "'" << p.first << "': ";
    first = false;
    const std::string type = p.second.typeName() ? p.second.typeName() : "";
    if (type == "int")
      out << p.second.toInt();
    else if (type == "double" || type == "float") {
      out.precision(6);
      out << p.second.toDouble();
    } else if (type == "bool")
      out << (p.second.toBool() ? "True" : "False");
    else
      out << "'" << p.second.toString().toStdString() << "'";
  }
  out << "}";
  return out.str();
}

// ---- MeshSet operations -----------------------------------------------------------------------

FilterPlugin* pluginFromFilterName(const QString& filterName, QAction*& action) {
  for (FilterPlugin* fp : meshlab::pluginManagerInstance().filterPluginIterator())
    for (QAction* act : fp->actions())
      if (filterName == fp->filterName(act)) {
        action = act;
        return fp;
      }
  throw MLException("Something really bad happened: no plugin has the filter " + filterName);
}

void printLog(MeshDocument& md, int& printed) {
  const auto& entries = md.Log.logStringList();
  for (; printed < entries.size(); ++printed)
    if (verbose) std::cerr << "log: " << entries[printed].second.toStdString() << "\n";
}

// MeshSet.apply_filter (pymeshlab/meshset.cpp) and meshsethelper::applyFilterRPL.
void applyFilter(MeshDocument& md, const std::string& name, const std::vector<Kwarg>& kwargs) {
  pymeshlab::FunctionSet& functions = pymeshlab::functionSetInstance();
  const QString pythonName = QString::fromStdString(name);
  if (!functions.containsFilterFunction(pythonName))
    throw MLException("Failed to apply filter: " + pythonName + "\n" +
                      "Filter does not exists. Take a look at MeshSet.print_filter_list function.");
  const pymeshlab::Function& f = functions.filterFunction(pythonName);
  QAction* action = nullptr;
  FilterPlugin* fp = pluginFromFilterName(f.meshlabFunctionName(), action);
  if (fp->filterArity(action) != FilterPlugin::NONE && md.meshNumber() == 0)
    throw MLException(pythonName + " requires at least one mesh loaded in the MeshSet.");
  RichParameterList rpl = fp->initParameterList(action, md);
  setKwargs(f, kwargs, rpl);

  QStringList missing;
  if (md.mm() && !fp->isFilterApplicable(action, *md.mm(), missing))
    throw MLException("Failed to apply filter:  '" + pythonName + ". Current mesh does not have " +
                      missing.join(",") + ".");
  if (fp->requiresGLContext(action))
    throw MLException("Failed to apply filter: " + pythonName +
                      "\nDetails: the filter needs an OpenGL context, which this host lacks");
  std::map<std::string, QVariant> values;
  if (verbose) fp->setLog(&md.Log);  // as pymeshlab: the filter's log only when verbose
  try {
    if (md.mm()) md.mm()->updateDataMask(fp->getRequirements(action));
    unsigned int postConditionMask = MeshModel::MM_UNKNOWN;
    values = fp->applyFilter(action, rpl, md, postConditionMask, &progress);
    for (MeshModel& mm : md.meshIterator()) vcg::tri::Allocator<CMeshO>::CompactEveryVector(mm.cm);
  } catch (const std::exception& e) {
    fp->setLog(nullptr);
    throw MLException("Failed to apply filter: " + pythonName + "\n" + "Details: " + e.what());
  }
  fp->setLog(nullptr);
  std::cout << name << " -> " << formatDict(values) << std::endl;
}

// meshsethelper::loadMeshUsingPlugin.
void loadMesh(MeshDocument& md, const std::string& file) {
  QFileInfo info(QString::fromStdString(file));
  const QString extension = info.suffix().toLower();
  if (!info.exists()) throw MLException("File does not exists: " + QString::fromStdString(file));
  PluginManager& pm = meshlab::pluginManagerInstance();
  if (!pm.isInputMeshFormatSupported(extension))
    throw MLException("Unknown format for load: " + extension);
  RichParameterList rps = pm.inputMeshPlugin(extension)->initPreOpenParameter(extension);
  try {
    meshlab::loadMeshWithStandardParameters(QString::fromStdString(file), md, &progress, rps);
  } catch (const MLException& e) {
    throw MLException("Unable to open file: " + QString::fromStdString(file) + "\n" + e.what());
  }
  const MeshModel& m = *md.mm();
  std::cout << "loaded " << file << ": " << m.cm.vn << " vertices, " << m.cm.fn << " faces"
            << std::endl;
}

void saveMesh(MeshModel* m, const std::string& file) {
  if (!m) throw MLException("MeshSet has no selected Mesh.");
  meshlab::saveMeshWithStandardParameters(QFileInfo(QString::fromStdString(file)).absoluteFilePath(), *m);
  std::cout << "saved " << m->label().toStdString() << " (" << m->cm.vn << " vertices, "
            << m->cm.fn << " faces, " << m->cm.en << " edges) to " << file << std::endl;
}

MeshModel* layerByLabel(MeshDocument& md, const std::string& label) {
  for (MeshModel& m : md.meshIterator())
    if (m.label().toStdString() == label) return &m;
  throw MLException("No mesh labelled '" + QString::fromStdString(label) + "' in the MeshSet.");
}

void printFilters() {
  for (const pymeshlab::Function& f : pymeshlab::functionSetInstance().filterFunctionIterator()) {
    std::cout << f.pythonFunctionName().toStdString() << "(";
    bool first = true;
    for (const pymeshlab::FunctionParameter& p : f) {
      std::cout << (first ? "" : ", ") << p.pythonName().toStdString() << ": "
                << p.pythonTypeString().toStdString() << " = ";
      p.printDefaultValue(std::cout);
      first = false;
    }
    std::cout << ")  # " << f.meshlabFunctionName().toStdString() << "\n";
  }
  std::cout << std::flush;
}

void loadPlugin(const std::string& file) {
  MeshLabPlugin* p = meshlab::pluginManagerInstance().loadPlugin(QString::fromStdString(file));
  const auto version = p->getMLVersion();
  std::cout << "loaded plugin " << p->pluginName().toStdString() << " from " << file
            << ": built for MeshLab " << version.first << " ("
            << (version.second ? "double" : "float") << "), this MeshLab "
            << meshlab::meshlabVersion() << " ("
            << (meshlab::builtWithDoublePrecision() ? "double" : "float") << ")" << std::endl;
}

bool isCommand(const std::string& w) {
  return w == "load_plugin" || w == "filters" || w == "load" || w == "apply" || w == "save" ||
         w == "save_layer" || w == "info";
}

int usage() {
  std::cerr << "usage: fcql_pymeshlab_host [--plugins DIR]... [--verbose] COMMAND...\n"
               "commands: load_plugin FILE | filters | load FILE | apply NAME [KEY=VALUE]... |\n"
               "          save FILE | save_layer LABEL FILE | info\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);  // QT_QPA_PLATFORM=offscreen: no display needed
  std::setlocale(LC_NUMERIC, "C");
  std::vector<std::string> args(argv + 1, argv + argc);
  std::vector<std::string> pluginDirs;
  std::size_t i = 0;
  for (; i < args.size(); ++i) {
    if (args[i] == "--plugins" && i + 1 < args.size())
      pluginDirs.push_back(args[++i]);
    else if (args[i] == "--verbose")
      verbose = true;
    else if (args[i] == "--help" || args[i] == "-h")
      return usage(), 0;
    else
      break;
  }
  if (i >= args.size()) return usage();
  if (pluginDirs.empty())
    for (const QString& d : QString(FCQL_HOST_DEFAULT_PLUGIN_DIRS).split(':', Qt::SkipEmptyParts))
      pluginDirs.push_back(d.toStdString());

  MeshDocument md;  // pymeshlab's MeshSet is a MeshDocument
  int logged = 0;
  try {
    for (const std::string& dir : pluginDirs)
      meshlab::pluginManagerInstance().loadPlugins(QDir(QString::fromStdString(dir)));
    while (i < args.size()) {
      const std::string command = args[i++];
      auto operand = [&](const char* what) {
        if (i >= args.size()) throw MLException(QString::fromStdString(command) + ": " + what + " missing");
        return args[i++];
      };
      if (command == "load_plugin") {
        loadPlugin(operand("FILE"));
      } else if (command == "filters") {
        printFilters();
      } else if (command == "load") {
        loadMesh(md, operand("FILE"));
      } else if (command == "apply") {
        const std::string name = operand("NAME");
        std::vector<Kwarg> kwargs;
        while (i < args.size() && !isCommand(args[i])) {
          const std::string& kv = args[i++];
          const std::size_t eq = kv.find('=');
          if (eq == std::string::npos || eq == 0)
            throw MLException("apply " + QString::fromStdString(name) + ": '" +
                              QString::fromStdString(kv) + "' is not KEY=VALUE");
          kwargs.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
        }
        applyFilter(md, name, kwargs);
      } else if (command == "save") {
        saveMesh(md.mm(), operand("FILE"));
      } else if (command == "save_layer") {
        const std::string label = operand("LABEL");
        saveMesh(layerByLabel(md, label), operand("FILE"));
      } else if (command == "info") {
        for (const MeshModel& m : md.meshIterator())
          std::cout << "mesh " << m.id() << " '" << m.label().toStdString() << "': " << m.cm.vn
                    << " vertices, " << m.cm.fn << " faces, " << m.cm.en << " edges\n";
        std::cout << std::flush;
      } else {
        throw MLException("unknown command '" + QString::fromStdString(command) + "'");
      }
      printLog(md, logged);
    }
  } catch (const MLException& e) {
    printLog(md, logged);
    std::cerr << "PyMeshLabException: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
