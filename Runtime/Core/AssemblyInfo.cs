using System.Runtime.CompilerServices;

// Unity builds assemblies from asmdefs and sources, never from Tools~'s csproj, so the tests' access to the core's
// internals must be declared here, in a source file of the core.
[assembly: InternalsVisibleTo("AvatarGo.Core.Tests")]
