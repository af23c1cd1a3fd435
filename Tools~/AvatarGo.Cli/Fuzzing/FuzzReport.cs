using System.Collections.Generic;

namespace AvatarGo.Cli.Fuzzing;

/// <summary>What a run of one target did.</summary>
internal sealed class FuzzReport
{
    public FuzzReport(string target) { Target = target; }

    public string Target { get; }
    public long Inputs { get; set; }
    public long Generated { get; set; }
    public long Parsed { get; set; }
    public long Failures { get; set; }
    public double Seconds { get; set; }
    public double SlowestMilliseconds { get; set; }
    public string SlowestInput { get; set; }
    public List<FuzzFinding> Findings { get; } = new();
}
