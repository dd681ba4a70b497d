#include "vtkGlassRankExchange.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <vector>

vtkStandardNewMacro(vtkGlassRankExchange);

vtkGlassRankExchange::vtkGlassRankExchange() = default;
vtkGlassRankExchange::~vtkGlassRankExchange() = default;

void vtkGlassRankExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller << "\n";
}

void vtkGlassRankExchange::SetController(vtkMultiProcessController* controller)
{
  if (controller != this->Controller)
  {
    this->Controller = controller;
    this->Modified();
  }
}

vtkMultiProcessController* vtkGlassRankExchange::GetController()
{
  return this->Controller ? this->Controller.GetPointer()
                          : vtkMultiProcessController::GetGlobalController();
}

int vtkGlassRankExchange::GetRank()
{
  vtkMultiProcessController* controller = this->GetController();
  return controller ? controller->GetLocalProcessId() : 0;
}

int vtkGlassRankExchange::GetNumberOfRanks()
{
  vtkMultiProcessController* controller = this->GetController();
  return controller ? controller->GetNumberOfProcesses() : 1;
}

void vtkGlassRankExchange::AllReduceMax(int* values, int count)
{
  vtkMultiProcessController* controller = this->GetController();
  if (!controller || controller->GetNumberOfProcesses() < 2 || count < 1)
  {
    return;
  }
  std::vector<int> local(values, values + count);
  ++this->AllReduces;
  controller->AllReduce(local.data(), values, count, vtkCommunicator::MAX_OP);
}

double vtkGlassRankExchange::AllReduceMin(double value)
{
  vtkMultiProcessController* controller = this->GetController();
  double result = value;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    ++this->AllReduces;
    controller->AllReduce(&value, &result, 1, vtkCommunicator::MIN_OP);
  }
  return result;
}

double vtkGlassRankExchange::AllReduceMax(double value)
{
  vtkMultiProcessController* controller = this->GetController();
  double result = value;
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    ++this->AllReduces;
    controller->AllReduce(&value, &result, 1, vtkCommunicator::MAX_OP);
  }
  return result;
}

bool vtkGlassRankExchange::Send(const unsigned char* data, unsigned long long bytes, int to)
{
  vtkMultiProcessController* controller = this->GetController();
  if (!controller)
  {
    return false;
  }
  ++this->Sends;
  return controller->Send(reinterpret_cast<const char*>(data), static_cast<vtkIdType>(bytes), to,
           BufferTag) != 0;
}

bool vtkGlassRankExchange::Receive(unsigned char* data, unsigned long long bytes, int from)
{
  vtkMultiProcessController* controller = this->GetController();
  if (!controller)
  {
    return false;
  }
  ++this->Receives;
  return controller->Receive(reinterpret_cast<char*>(data), static_cast<vtkIdType>(bytes), from,
           BufferTag) != 0;
}
