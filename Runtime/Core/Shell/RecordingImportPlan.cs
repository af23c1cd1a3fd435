namespace AvatarGo.Core
{
    /// <summary>What the Editor's import menu does with one file: import it under <see cref="TargetFileName"/>, or show <see cref="Error"/>.</summary>
    public sealed class RecordingImportPlan
    {
        internal RecordingImportPlan(bool isValid, RecordingFileKind kind, string targetFileName, string summary, string error)
        {
            IsValid = isValid;
            Kind = kind;
            TargetFileName = targetFileName;
            Summary = summary;
            Error = error;
        }

        /// <summary>True when the file was read to its end by the core reader without a format error.</summary>
        public bool IsValid { get; }

        /// <summary>What the file holds (taken from its name, else from its first word).</summary>
        public RecordingFileKind Kind { get; }

        /// <summary>
        /// The text asset's file name (<c>NAME.agsession.txt</c> or <c>NAME.bvh.txt</c>, so that Unity imports a
        /// <c>TextAsset</c>); null when the file is not valid.
        /// </summary>
        public string TargetFileName { get; }

        /// <summary>What was read (frames, devices, joints), for the log; null when not valid.</summary>
        public string Summary { get; }

        /// <summary>
        /// Why the file is not imported: the reader's <c>FILE:LINE: problem</c> message, or why it could not be read;
        /// null when valid.
        /// </summary>
        public string Error { get; }
    }
}
