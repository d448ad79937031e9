// Records tick-by-tick traces of small Behavior Trees from BehaviorTree.CPP itself, so that
// LogicEnvEval's engine can be compared against the real one (tests/test_btcpp_conformance.py).
//
// Our program; it links BehaviorTree.CPP 4.x (recorded with 4.10.0) and uses the JSON header
// that BT.CPP installs. Usage:  recorder CASES.json TRACES.json
// (BT.CPP prints its own warnings on stdout, so the traces go to a file).
//
// Every leaf is a stub registered under an action/condition name of our library (Pick, Open,
// Close: actions; Holding, Near, Exists: conditions; one port `obj`). A stub returns the
// statuses scripted for its `name` attribute, one per tick of the stub (the last one repeats);
// an action may return RUNNING, a condition only SUCCESS/FAILURE. Each root tick is one
// `Tree::tickExactlyOnce()`, until the root is not RUNNING or `max_ticks` ticks were made.
// Output per case: the events of each tick (stub name + returned status, or HALTED when BT.CPP
// halts a RUNNING stub) with the root status, or the error BT.CPP raised (at load or tick).
//
// Second use:  recorder --model MODEL.json MODEL.xml  registers the leaves MODEL.json lists
// (tag, ID, description, input ports with their descriptions) and writes the Groot2
// <TreeNodesModel> BT.CPP prints for them (writeTreeNodesModelXML, built-in nodes left out).
#include <behaviortree_cpp/bt_factory.h>
#include <behaviortree_cpp/xml_parsing.h>
#include <behaviortree_cpp/contrib/json.hpp>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

using nlohmann::json;

namespace
{
struct Recorder
{
  std::map<std::string, std::vector<std::string>> scripts;
  std::map<std::string, size_t> used;
  json events = json::array();

  BT::NodeStatus next(const std::string& name)
  {
    const auto& script = scripts.at(name);
    size_t& i = used[name];
    const std::string& word = script.at(std::min(i, script.size() - 1));
    ++i;
    events.push_back({ name, word });
    if(word == "SUCCESS")
      return BT::NodeStatus::SUCCESS;
    if(word == "FAILURE")
      return BT::NodeStatus::FAILURE;
    return BT::NodeStatus::RUNNING;
  }
};

class StubAction : public BT::StatefulActionNode
{
public:
  StubAction(const std::string& name, const BT::NodeConfig& config, Recorder* rec)
    : BT::StatefulActionNode(name, config), rec_(rec)
  {}
  BT::NodeStatus onStart() override { return rec_->next(name()); }
  BT::NodeStatus onRunning() override { return rec_->next(name()); }
  void onHalted() override { rec_->events.push_back({ name(), "HALTED" }); }

private:
  Recorder* rec_;
};

class StubCondition : public BT::ConditionNode
{
public:
  StubCondition(const std::string& name, const BT::NodeConfig& config, Recorder* rec)
    : BT::ConditionNode(name, config), rec_(rec)
  {}
  BT::NodeStatus tick() override { return rec_->next(name()); }

private:
  Recorder* rec_;
};

const char* word(BT::NodeStatus st)
{
  switch(st)
  {
    case BT::NodeStatus::SUCCESS:
      return "SUCCESS";
    case BT::NodeStatus::FAILURE:
      return "FAILURE";
    case BT::NodeStatus::RUNNING:
      return "RUNNING";
    case BT::NodeStatus::SKIPPED:
      return "SKIPPED";
    default:
      return "IDLE";
  }
}

json record(const json& c)
{
  Recorder rec;
  for(const auto& [name, script] : c.at("scripts").items())
  {
    rec.scripts[name] = script.get<std::vector<std::string>>();
  }
  BT::BehaviorTreeFactory factory;
  const BT::PortsList ports = { BT::InputPort<std::string>("obj") };
  for(const char* id : { "Pick", "Open", "Close" })
  {
    factory.registerNodeType<StubAction>(id, ports, &rec);
  }
  for(const char* id : { "Holding", "Near", "Exists" })
  {
    factory.registerNodeType<StubCondition>(id, ports, &rec);
  }
  json out = { { "id", c.at("id") } };
  std::string stage = "load";
  try
  {
    auto tree = factory.createTreeFromText(c.at("xml").get<std::string>());
    stage = "tick";
    json ticks = json::array();
    const int max_ticks = c.value("max_ticks", 20);
    BT::NodeStatus st = BT::NodeStatus::RUNNING;
    for(int t = 1; t <= max_ticks && st == BT::NodeStatus::RUNNING; ++t)
    {
      rec.events = json::array();
      st = tree.tickExactlyOnce();
      ticks.push_back({ { "events", rec.events }, { "root", word(st) } });
    }
    out["ticks"] = ticks;
    out["status"] = word(st);
  }
  catch(const std::exception& ex)
  {
    out["error"] = { { "stage", stage }, { "message", ex.what() } };
  }
  return out;
}
}  // namespace

int writeModel(const char* spec_path, const char* out_path)
{
  std::ifstream in(spec_path);
  const json spec = json::parse(in);
  Recorder rec;
  BT::BehaviorTreeFactory factory;
  for(const auto& e : spec.at("entries"))
  {
    BT::PortsList ports;
    for(const auto& p : e.at("ports"))
    {
      ports.insert(BT::InputPort<std::string>(p.at(0).get<std::string>(),
                                              p.at(1).get<std::string>()));
    }
    const auto id = e.at("id").get<std::string>();
    if(e.at("tag") == "Action")
    {
      factory.registerNodeType<StubAction>(id, ports, &rec);
    }
    else
    {
      factory.registerNodeType<StubCondition>(id, ports, &rec);
    }
    factory.addMetadataToManifest(id, { { "description", e.at("description").get<std::string>() } });
  }
  std::ofstream(out_path) << BT::writeTreeNodesModelXML(factory, false) << "\n";
  return 0;
}

int main(int argc, char** argv)
{
  if(argc == 4 && std::string(argv[1]) == "--model")
  {
    return writeModel(argv[2], argv[3]);
  }
  if(argc != 3)
  {
    std::cerr << "usage: recorder CASES.json TRACES.json | recorder --model MODEL.json MODEL.xml\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  const json cases = json::parse(in);
  json out = { { "engine", std::string("BehaviorTree.CPP ") + BT::LibraryVersionString() },
               { "cases", json::array() } };
  for(const auto& c : cases.at("cases"))
  {
    out["cases"].push_back(record(c));
  }
  std::ofstream(argv[2]) << out.dump(1) << "\n";
  return 0;
}
