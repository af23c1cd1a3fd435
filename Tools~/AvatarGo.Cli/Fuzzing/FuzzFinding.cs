namespace AvatarGo.Cli.Fuzzing;

/// <summary>One kind of failure: how many inputs showed it, the first one's origin, and its minimised example.</summary>
internal sealed class FuzzFinding
{
    public FuzzFinding(string bucket, string description, string origin)
    {
        Bucket = bucket;
        Description = description;
        Origin = origin;
    }

    public string Bucket { get; }
    public string Description { get; }
    public string Origin { get; }
    public int Count { get; set; }
    public string Example { get; set; }
    public string SavedAs { get; set; }
}
