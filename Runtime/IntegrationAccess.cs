using System.Runtime.CompilerServices;

// The optional integration assemblies (Runtime/<Integration>/, compiled only when their package is present) use the
// AvatarGo assembly's internals: AvatarGoDocs for their components' HelpURLs.
[assembly: InternalsVisibleTo("AvatarGo.InputSystem")]
[assembly: InternalsVisibleTo("AvatarGo.OpenXR")]
[assembly: InternalsVisibleTo("AvatarGo.SteamVR")]
[assembly: InternalsVisibleTo("AvatarGo.XRInteractionToolkit")]
