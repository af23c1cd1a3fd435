using System;
using System.IO;
using System.Linq;

namespace AvatarGo.Tools.Tests.PackageLint;

/// <summary>
/// A minimal, lint-clean copy of the package layout in a temporary folder, for planting one defect at
/// a time and checking that <see cref="PackageLinter"/> reports it. Disposing deletes the folder.
/// </summary>
public sealed class FakePackage : IDisposable
{
    /// <summary>Creates the clean fake package (files, folders and .meta files with fresh GUIDs).</summary>
    public FakePackage()
    {
        Root = Path.Combine(Path.GetTempPath(), "avatargo-lint-" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(Root);
        Write("package.json", """
            {
              "name": "com.avatargo.selfavatar",
              "displayName": "AvatarGo Self-Avatar",
              "version": "0.1.0",
              "unity": "2021.3",
              "description": "Fake package for lint tests.",
              "author": { "name": "Tests" },
              "license": "MIT",
              "samples": [ { "displayName": "Demo", "description": "d", "path": "Samples~/Demo" } ]
            }
            """);
        Write("README.md", "# Fake\n");
        Write("CHANGELOG.md", "# Changelog\n\n## [Unreleased]\n\n### Added\n- Something.\n\n## [0.1.0] - 2024-01-31\n\n### Fixed\n- A bug.\n");
        Write("LICENSE.md", "MIT License\n\nCopyright (c) 2024 Tests\n");
        Write("Third Party Notices.md", "None.\n");
        Write("Documentation~/index.md", "# Manual\n\nHow to use it.\n");
        Write("Samples~/Demo/README.md", "Demo\n");
        Write("Tools~/AvatarGo.Core/AvatarGo.Core.csproj", "<Project />\n");
        Write("Tools~/AvatarGo.Core/bin/Release/x.dll", "");
        Write("Runtime/AvatarGo.asmdef", Asmdef("AvatarGo", "\"AvatarGo.Core\""));
        Write("Runtime/Core/AvatarGo.Core.asmdef", Asmdef("AvatarGo.Core", "", noEngineReferences: true));
        Write("Runtime/Core/AssemblyInfo.cs", "[assembly: System.Runtime.CompilerServices.InternalsVisibleTo(\"AvatarGo.Core.Tests\")]\n");
        Write("Runtime/Simulation/AvatarGo.Simulation.asmdef", Asmdef("AvatarGo.Simulation", "\"AvatarGo.Core\"", noEngineReferences: true,
            constraints: "\"UNITY_EDITOR || UNITY_INCLUDE_TESTS\"", autoReferenced: false));
        Write("Runtime/Core/Math/Thing.cs", "namespace AvatarGo.Core\n{\n    /// <summary>x</summary>\n    public struct Thing { }\n}\n");
        Write("Runtime/Behaviours/Driver.cs", "using UnityEngine;\n\nnamespace AvatarGo;\n\npublic sealed class Driver : MonoBehaviour\n{\n    public enum Mode { A, B }\n}\n");
        Write("Editor/AvatarGo.Editor.asmdef", Asmdef("AvatarGo.Editor", "\"AvatarGo\"", platforms: "\"Editor\""));
        Write("Tests/Core/AvatarGo.Core.Tests.asmdef", Asmdef("AvatarGo.Core.Tests",
            "\"AvatarGo.Core\", \"UnityEngine.TestRunner\", \"UnityEditor.TestRunner\"", platforms: "\"Editor\"", test: true));
        Write("Tests/Core/Math/ThingTests.cs", "namespace AvatarGo.Core.Tests\n{\n    public class ThingTests { internal class Helper { } }\n    internal static class Extra { }\n}\n");
        MakeMetas();
    }

    /// <summary>The fake package root.</summary>
    public string Root { get; }

    /// <summary>A linter for the fake package (a fresh one, so file listings are current).</summary>
    public PackageLinter Linter => new(Root);

    /// <summary>Writes a file (relative path with '/'), creating folders.</summary>
    public void Write(string relative, string text)
    {
        string path = Path.Combine(Root, relative);
        Directory.CreateDirectory(Path.GetDirectoryName(path));
        File.WriteAllText(path, text.Replace("\r\n", "\n"));
    }

    /// <summary>Reads a file.</summary>
    public string Read(string relative) => File.ReadAllText(Path.Combine(Root, relative));

    /// <summary>Deletes a file.</summary>
    public void Delete(string relative) => File.Delete(Path.Combine(Root, relative));

    /// <summary>The GUID in a .meta.</summary>
    public string GuidOf(string relativeMeta) =>
        File.ReadLines(Path.Combine(Root, relativeMeta)).First(l => l.StartsWith("guid:", StringComparison.Ordinal)).Substring(5).Trim();

    /// <summary>Writes a .meta for every imported file and folder that lacks one (like Tools~/make-metas.py).</summary>
    public void MakeMetas()
    {
        foreach (string path in Directory.GetFileSystemEntries(Root, "*", SearchOption.AllDirectories))
        {
            string rel = Path.GetRelativePath(Root, path).Replace('\\', '/');
            if (rel.EndsWith(".meta", StringComparison.Ordinal) || !PackageLinter.IsImported(rel)) continue;
            if (File.Exists(path + ".meta")) continue;
            File.WriteAllText(path + ".meta", Meta(rel, Directory.Exists(path)));
        }
    }

    /// <summary>The .meta text Unity would write for an asset.</summary>
    public static string Meta(string relative, bool folder, string guid = null)
    {
        string importer = folder ? "folderAsset: yes\nDefaultImporter:" :
            relative.EndsWith("package.json", StringComparison.Ordinal) ? "PackageManifestImporter:" :
            relative.EndsWith(".cs", StringComparison.Ordinal) ? "MonoImporter:\n  serializedVersion: 2" :
            relative.EndsWith(".asmdef", StringComparison.Ordinal) ? "AssemblyDefinitionImporter:" :
            relative.EndsWith(".md", StringComparison.Ordinal) ? "TextScriptImporter:" : "DefaultImporter:";
        return $"fileFormatVersion: 2\nguid: {guid ?? Guid.NewGuid().ToString("N")}\n{importer}\n  externalObjects: {{}}\n  userData: \n";
    }

    /// <summary>An asmdef's JSON.</summary>
    public static string Asmdef(string name, string references, string platforms = "", bool test = false, bool noEngineReferences = false,
        string constraints = null, bool autoReferenced = true) =>
        "{\n" +
        $"    \"name\": \"{name}\",\n" +
        $"    \"references\": [{references}],\n" +
        $"    \"includePlatforms\": [{platforms}],\n" +
        $"    \"overrideReferences\": {(test ? "true" : "false")},\n" +
        $"    \"precompiledReferences\": [{(test ? "\"nunit.framework.dll\"" : "")}],\n" +
        $"    \"defineConstraints\": [{constraints ?? (test ? "\"UNITY_INCLUDE_TESTS\"" : "")}],\n" +
        $"    \"autoReferenced\": {(autoReferenced ? "true" : "false")},\n" +
        $"    \"noEngineReferences\": {(noEngineReferences ? "true" : "false")}\n" +
        "}\n";

    /// <summary>Deletes the temporary folder.</summary>
    public void Dispose()
    {
        try
        {
            Directory.Delete(Root, recursive: true);
        }
        catch (IOException)
        {
            // A leftover temp folder is harmless.
        }
    }
}
