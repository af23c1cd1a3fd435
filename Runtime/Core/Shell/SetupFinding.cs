namespace AvatarGo.Core
{
    /// <summary>One thing an inspector tells the developer about the assigned avatar.</summary>
    public readonly struct SetupFinding
    {
        /// <summary>Creates a finding.</summary>
        public SetupFinding(SetupSeverity severity, string message, SetupFix fix = SetupFix.None)
        {
            Severity = severity;
            Message = message;
            Fix = fix;
        }

        /// <summary>How much it matters.</summary>
        public SetupSeverity Severity { get; }

        /// <summary>What is wrong and what to do, in one or two sentences.</summary>
        public string Message { get; }

        /// <summary>The fix a button can apply, or <see cref="SetupFix.None"/>.</summary>
        public SetupFix Fix { get; }

        /// <inheritdoc/>
        public override string ToString() => $"{Severity}: {Message}";
    }
}
