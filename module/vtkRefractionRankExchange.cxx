#include "vtkRefractionRankExchange.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkRefractionRankExchange);

vtkRefractionRankExchange::vtkRefractionRankExchange() = default;
vtkRefractionRankExchange::~vtkRefractionRankExchange() = default;

void vtkRefractionRankExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Rank: " << this->GetRank() << " of " << this->GetNumberOfRanks() << "\n";
}

void vtkRefractionRankExchange::AllReduceMax(int*, int) {}

bool vtkRefractionRankExchange::Send(const unsigned char*, unsigned long long, int)
{
  vtkErrorMacro("One process alone has no rank to send to.");
  return false;
}

bool vtkRefractionRankExchange::Receive(unsigned char*, unsigned long long, int)
{
  vtkErrorMacro("One process alone has no rank to receive from.");
  return false;
}
