// Shared by every compute shader (included after the layout(local_size_x) line): the flat item index of a dispatch spread over x and y
// (ComputeProgram::dispatch puts groups beyond 65535 into y).
uint workgroupIndex() {
    return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
}

uint itemIndex() {
    return workgroupIndex() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
}
