using System;

namespace AvatarGo.UnityGate;

/// <summary>A package that Unity could not set up for compilation (a broken asmdef, a reference to nothing, ...).</summary>
public sealed class GateException : Exception
{
    /// <summary>Creates the exception with a message naming the file and the problem.</summary>
    public GateException(string message) : base(message)
    {
    }
}
