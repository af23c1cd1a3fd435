using System;
using System.IO;
using NUnit.Framework;

namespace AvatarGo.Tools.Tests;

/// <summary>Tests that write files: each test gets a fresh folder under the temporary path, deleted after it.</summary>
public abstract class TempFolderTests
{
    /// <summary>This test's folder.</summary>
    protected string Dir { get; private set; }

    [SetUp]
    public void MakeFolder()
    {
        Dir = Path.Combine(Path.GetTempPath(), "avatargo-" + GetType().Name + "-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(Dir);
    }

    [TearDown]
    public void RemoveFolder()
    {
        if (Directory.Exists(Dir)) Directory.Delete(Dir, true);
    }
}
